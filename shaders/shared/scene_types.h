// The scene and frame as the path tracer sees them, and the wavefront's path
// state and queues: GPU structs shared by GLSL (scalar block layout) and C++.
#ifndef QLIGHT_SHARED_SCENE_TYPES_H
#define QLIGHT_SHARED_SCENE_TYPES_H
#include "bindings.h"
#include "common.h"

QL_BEGIN

// The path passes read triangles, vertices, materials and the light CDF from
// texel buffers (whole texels load at once on lavapipe): each struct below is
// a whole number of 16-byte texels, and integers that share a texel with
// floats are stored as float values (exact below 2^24), never as bit patterns.

// One triangle's shading data; BVH hits map to it through GpuInstance.firstTriangle.
// Two RGBA32UI texels.
struct GpuTriangle {
  uint v0, v1, v2;  // indices into the vertex array (already offset per mesh)
  uint material;
  uint light;  // index into the light list when emissive, else kNoLight
  // Texel of vertex v's GpuVertexExtras is vertexExtras + 3 v (mod 2^32: the mesh's extras
  // start minus 3 x its first vertex), kNoVertexExtras when its mesh has none.
  uint vertexExtras;
  uint pad1, pad2;
};
QL_CHECK_SIZE(GpuTriangle, 32);
QL_CONST uint kNoLight = 0xffffffffu;
QL_CONST uint kNoVertexExtras = 0xffffffffu;

// Two RGBA32F texels: (position, u), (normal, v), object space.
struct GpuVertex {
  vec3 position;
  float u;
  vec3 normal;
  float v;
};
QL_CHECK_SIZE(GpuVertex, 32);

// The optional attributes of a mesh's vertices (TEXCOORD_1, COLOR_0, TANGENT): three
// RGBA32F texels in the vertex buffer after all GpuVertex entries, only for meshes that
// have one of them.
struct GpuVertexExtras {
  vec4 tangent;  // object space xyz, w = +-1; (0,0,0,0): none
  vec4 color;    // linear RGBA, white when the file has none
  vec2 uv1;
  vec2 pad;
};
QL_CHECK_SIZE(GpuVertexExtras, 48);
QL_CONST uint kVertexExtrasTexels = 3u;

// Per BVH instance: where its mesh's triangles start and how to move normals and tangents
// to world space.
struct GpuInstance {
  vec4 normalFromObject[3];   // rows of transpose(inverse(M)) (xyz), w unused
  vec4 tangentFromObject[3];  // rows of M's linear part (xyz), w unused
  uint firstTriangle;
  uint mesh;
  float worldScale;  // the longest image of a unit axis under M: world size of object units
  uint pad1;
};
QL_CHECK_SIZE(GpuInstance, 112);
// RGBA32UI texels an instance takes in its texel buffer (include/scene_access.glsl).
QL_CONST uint kInstanceTexels = 7u;

QL_CONST uint kMaterialDoubleSided = 1u;
QL_CONST uint kMaterialUnlit = 2u;  // KHR_materials_unlit: emits its base colour, scatters nothing
// alphaMode MASK (opaque where alpha >= alphaCutoff, else absent) and BLEND (stochastic
// transparency: present with probability alpha), for every ray, shadow rays included.
QL_CONST uint kMaterialAlphaMask = 4u;
QL_CONST uint kMaterialAlphaBlend = 8u;
// KHR_materials_volume: transmission refracts into and out of a solid (else thin-walled).
QL_CONST uint kMaterialVolume = 16u;

// How a material reads one texture (KHR_texture_transform as a 2x3 matrix):
// uv' = (a u + b v + offsetU, c u + d v + offsetV) on UV set texCoord.
struct GpuTextureView {
  vec4 uRow;  // a, b, offsetU, texCoord (0 or 1)
  vec4 vRow;  // c, d, offsetV, texture index as a float value (-1: none)
};
QL_CHECK_SIZE(GpuTextureView, 32);
QL_CONST uint kTextureSlotBaseColor = 0u;
QL_CONST uint kTextureSlotMetallicRoughness = 1u;
QL_CONST uint kTextureSlotEmissive = 2u;
QL_CONST uint kTextureSlotNormal = 3u;
QL_CONST uint kTextureSlots = 4u;

// Twelve RGBA32F texels: four of factors, then a GpuTextureView per slot.
struct GpuMaterial {
  vec4 baseColor;  // linear RGBA
  vec3 emissive;   // linear radiance (factor x strength)
  float metallic;
  float roughness;
  float specular;  // KHR_materials_specular specularFactor (1 = plain glTF)
  float flags;     // kMaterial* bits, as a float value
  float normalScale;
  float alphaCutoff;
  float transmission;  // KHR_materials_transmission transmissionFactor
  float ior;           // KHR_materials_ior (1.5 = plain glTF)
  float pad0;
  GpuTextureView textures[kTextureSlots];
};
QL_CHECK_SIZE(GpuMaterial, 192);
QL_CONST uint kMaterialTexels = 12u;
QL_CONST uint kMaterialFactorTexels = 4u;

// Textures live in one uint texel buffer (RGBA8 packed), each at an offset.
QL_CONST uint kTextureSrgb = 1u;
QL_CONST uint kTextureNearest = 2u;
QL_CONST uint kTextureClampS = 4u;
QL_CONST uint kTextureClampT = 8u;
QL_CONST uint kTextureMirrorS = 16u;
QL_CONST uint kTextureMirrorT = 32u;
// flags >> kTextureLevelShift: mip levels, stored level 0 first from offset, each half the
// previous size (at least 1).
QL_CONST uint kTextureLevelShift = 8u;
struct GpuTexture {
  uint offset;
  uint width;
  uint height;
  uint flags;
};
QL_CHECK_SIZE(GpuTexture, 16);

QL_CONST uint kLightTriangle = 0u;
QL_CONST uint kLightPoint = 1u;
QL_CONST uint kLightSpot = 2u;
QL_CONST uint kLightDirectional = 3u;
// The light at infinity, always the last light: the user's environment map or uniform sky,
// or the uniform fallback sky of scenes without any light.
QL_CONST uint kLightSky = 4u;
QL_CONST uint kLightDoubleSided = 1u;
QL_CONST uint kLightMirrored =
    2u;  // triangle under a mirroring transform: front normal is -(e1 x e2)
QL_CONST uint kLightEnvironmentMap = 4u;  // sky: radiance = emission x the map (environment.h)

struct GpuLight {
  vec3 position;  // triangle: world vertex 0; point/spot: position
  uint type;
  vec3 edge1;     // triangle: v1 - v0; spot/directional: unit direction the light points to
  uint triangle;  // triangle: its GpuTriangle index (emissive textures); sky map: its tile
  vec3 edge2;     // triangle: v2 - v0
  float area;     // triangle: world area
  vec3 emission;  // triangle: radiance; point/spot: intensity (W/sr); directional: irradiance; sky:
                  // radiance (with kLightEnvironmentMap: the map's scale)
  float cosInner;
  float cosOuter;
  float range;  // 0: infinite
  uint flags;   // kLightDoubleSided, kLightMirrored, kLightEnvironmentMap
  float power;  // selection weight (proportional to emitted power)
};
QL_CHECK_SIZE(GpuLight, 80);
// RGBA32UI texels a light takes in its texel buffer (include/lights.glsl).
QL_CONST uint kLightTexels = 5u;

struct GpuCamera {
  vec3 position;
  float tanHalfFovY;
  vec3 forward;
  float aspect;
  vec3 right;
  float pad0;
  vec3 up;
  float pad1;
};
QL_CHECK_SIZE(GpuCamera, 64);

// Estimator switches (FrameUniforms.flags).
QL_CONST uint kFlagNee = 1u;          // next event estimation on
QL_CONST uint kFlagEmitterHits = 2u;  // BSDF-sampled rays that hit emitters count
QL_CONST uint kFlagMis = 4u;          // weight both by the power heuristic (needs both)
QL_CONST uint kFlagRussianRoulette = 8u;

struct FrameUniforms {
  GpuCamera camera;
  uvec2 resolution;
  uint frameIndex;  // samples accumulated before this frame (seeds the RNG)
  uint seed;
  uint maxDepth;  // bounces: 0 shows emitters only, 1 adds direct light
  uint flags;
  uint lightCount;
  uint samplesPerFrame;
  vec3 sceneCenter;
  float sceneRadius;  // for directional and sky light sampling
};
QL_CHECK_SIZE(FrameUniforms, 112);

// Counters the path tracer accumulates per frame (read back once per frame).
QL_CONST uint kStatRays = 0u;  // every ray traced, shadow rays included
QL_CONST uint kStatShadowRays = 1u;
QL_CONST uint kStatPaths = 2u;
QL_CONST uint kStatEmitterHits = 3u;  // paths whose scattered (not shadow) ray reached an emitter
QL_CONST uint kStatPathVertices =
    4u;  // sum of path lengths: scattering vertices until the path ends or first reaches an emitter
         // by a scattered ray (D&K's measure)
QL_CONST uint kStatInvalidSamples = 5u;   // NaN/Inf samples dropped (should stay 0)
QL_CONST uint kStatCoveredVertices = 6u;  // scattering vertices that found a cache point
QL_CONST uint kStatCount = 8u;

// The path tracer runs as a wavefront: begin (camera rays), then per bounce
// trace (pending shadow ray + extension ray) and shade, a last trace for the
// final shadow rays, and end (accumulate); pt_queue sizes the dispatch of each
// trace and shade. Path state lives between passes in a storage texel buffer
// (whole-texel loads and stores vectorize on lavapipe).
struct TracePush {
  uint sampleIndex;  // which of the frame's samples this dispatch takes
  uint bounce;       // path depth of the pass (every live path is at the same depth)
  uint extend;       // pt_queue: 1 = a sample starts (every path queued)
  uint pathCount;
};
QL_CHECK_SIZE(TracePush, 16);

// Workgroup size of every path pass (and of pt_queue's dispatch sizes).
#define QL_PATH_GROUP_SIZE 64
QL_CONST uint kPathGroupSize = QL_PATH_GROUP_SIZE;

// One path's state: kPathStateTexels RGBA32UI texels, packed and unpacked by
// shaders/include/path_state.glsl. Passes that need only a few fields read
// and write their texels directly. On lavapipe every texel a pass stores is
// a per-lane, per-component loop (about 2.5 ms a frame at 320x180 for each
// texel the shade pass writes): the trace pass writes only its two hit texels,
// and the shade pass traces its shadow ray itself, so no shadow ray waits here.
QL_CONST uint kPathTexelOrigin = 0u;         // origin, prevPoint
QL_CONST uint kPathTexelDir = 1u;            // dir, rng
QL_CONST uint kPathTexelThroughput = 2u;     // throughput, prevScatterPdf
QL_CONST uint kPathTexelRadianceFlags = 3u;  // radiance, flags
QL_CONST uint kPathTexelHit = 4u;            // hitT, hitU, hitV, hitInstance (trace)
QL_CONST uint kPathTexelHitPrimitive = 5u;   // hitPrimitive, 0, 0, 0 (trace)
QL_CONST uint kPathTexelCounters = 6u;       // vertices | covered << 16, half2(cone width, cone
                                             // spread), rays | shadowRays << 16, prevEntry
// Learning from returns (shaders/include/learning_returns.glsl): the last
// kReturnRecords vertices' Q entry, radiance so far and throughput, a ring.
QL_CONST uint kReturnRecords = 4u;
// Guided Russian roulette (pt_shade.comp): the path's expected radiance at its
// first vertex, written there, read at each later roulette.
QL_CONST uint kPathTexelRouletteScale = 7u;  // expected radiance, 0, 0, 0
QL_CONST uint kPathTexelReturnRecords = 8u;  // entry, luminance(radiance), luminance(throughput), 0
QL_CONST uint kPathStateTexels = kPathTexelReturnRecords + kReturnRecords;

// Per queue (two: the current and the next): its count and the indirect
// dispatch that covers it. groupsX..Z are a VkDispatchIndirectCommand, at
// offsetof(QueueState, groupsX) in each.
struct QueueState {
  uint count;
  uint groupsX, groupsY, groupsZ;
};
QL_CHECK_SIZE(QueueState, 16);

QL_END

#endif
