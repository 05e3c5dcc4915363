// Scene buffers of the path tracer and the hit -> surface resolution.
// Included by the path tracing and guiding passes after the shared headers.
#include "include/features.glsl"
#include "shared/random.h"
#include "shared/bvh_types.h"

// Tables read at per-lane indices are texel buffers: on lavapipe a texel load fetches all
// lanes at once where a storage-buffer load loops over the lanes for each 32-bit word, and
// imageLoad on a read-only imageBuffer beats texelFetch on a samplerBuffer (4-11% faster
// traversal, docs/performance_log.md). Integer views, so the uint fields' bits come back as
// stored on any GPU. Texels per entry: triangles and vertices 2, instances kInstanceTexels,
// materials 4, texture headers 1.
layout(binding = QL_BIND_BVH_NODES, rgba32f) uniform readonly restrict imageBuffer uBvhNodes;
layout(binding = QL_BIND_BVH_TRIS, rgba32f) uniform readonly restrict imageBuffer uBvhTris;
layout(binding = QL_BIND_BVH_INSTANCES, rgba32f) uniform readonly restrict imageBuffer uBvhInst;
#define QL_BVH_NODE(i) imageLoad(uBvhNodes, int(i))
#define QL_BVH_TRI(i) imageLoad(uBvhTris, int(i))
#define QL_BVH_INST(i) imageLoad(uBvhInst, int(i))

layout(binding = QL_BIND_TRIANGLES, rgba32ui) uniform readonly restrict uimageBuffer uTriangles;
layout(binding = QL_BIND_VERTICES, rgba32f) uniform readonly restrict imageBuffer uVertices;
layout(binding = QL_BIND_INSTANCES, rgba32ui) uniform readonly restrict uimageBuffer uInstances;
layout(binding = QL_BIND_MATERIALS, rgba32f) uniform readonly restrict imageBuffer uMaterials;
layout(binding = QL_BIND_TEXTURES, rgba32ui) uniform readonly restrict uimageBuffer uTextures;
layout(binding = QL_BIND_TEXELS, r32ui) uniform readonly restrict uimageBuffer uTexels;

// Only the fields a caller uses are fetched: the compiler drops the others' texels.
GpuInstance instanceAt(uint i) {
  int at = int(kInstanceTexels * i);
  GpuInstance inst;
  for (int r = 0; r < 3; ++r) {
    inst.normalFromObject[r] = uintBitsToFloat(imageLoad(uInstances, at + r));
    inst.tangentFromObject[r] = uintBitsToFloat(imageLoad(uInstances, at + 3 + r));
  }
  uvec4 info = imageLoad(uInstances, at + 6);
  inst.firstTriangle = info.x;
  inst.mesh = info.y;
  inst.worldScale = uintBitsToFloat(info.z);
  inst.pad1 = 0u;
  return inst;
}

uint instanceFirstTriangle(uint i) {
  return imageLoad(uInstances, int(kInstanceTexels * i + 6u)).x;
}

GpuTexture textureAt(uint i) {
  uvec4 t = imageLoad(uTextures, int(i));
  return GpuTexture(t.x, t.y, t.z, t.w);
}

GpuTriangle triangleAt(uint i) {
  uvec4 a = imageLoad(uTriangles, int(2u * i));
  uvec4 b = imageLoad(uTriangles, int(2u * i + 1u));
  GpuTriangle t;
  t.v0 = a.x;
  t.v1 = a.y;
  t.v2 = a.z;
  t.material = a.w;
  t.light = b.x;
  t.vertexExtras = b.y;
  t.pad1 = t.pad2 = 0u;
  return t;
}

GpuVertex vertexAt(uint i) {
  vec4 a = imageLoad(uVertices, int(2u * i));
  vec4 b = imageLoad(uVertices, int(2u * i + 1u));
  GpuVertex v;
  v.position = a.xyz;
  v.u = a.w;
  v.normal = b.xyz;
  v.v = b.w;
  return v;
}

GpuVertexExtras vertexExtrasAt(uint extrasTexel, uint i) {
  int at = int(extrasTexel + kVertexExtrasTexels * i);
  GpuVertexExtras e;
  e.tangent = imageLoad(uVertices, at);
  e.color = imageLoad(uVertices, at + 1);
  e.uv1 = imageLoad(uVertices, at + 2).xy;
  e.pad = vec2(0.0);
  return e;
}

vec2 vertexUv(uint i) {
  return vec2(imageLoad(uVertices, int(2u * i)).w, imageLoad(uVertices, int(2u * i + 1u)).w);
}

// The factors only; a texture slot's view is read by textureViewAt when it is used.
GpuMaterial materialAt(uint i) {
  int at = int(kMaterialTexels * i);
  vec4 a = imageLoad(uMaterials, at);
  vec4 b = imageLoad(uMaterials, at + 1);
  vec4 c = imageLoad(uMaterials, at + 2);
  GpuMaterial m;
  m.baseColor = a;
  m.emissive = b.xyz;
  m.metallic = b.w;
  m.roughness = c.x;
  m.specular = c.y;
  m.flags = c.z;
  m.normalScale = c.w;
  vec4 d = imageLoad(uMaterials, at + 3);
  m.alphaCutoff = d.x;
  m.transmission = d.y;
  m.ior = d.z;
  m.pad0 = 0.0;
  return m;
}

GpuTextureView textureViewAt(uint material, uint slot) {
  int at = int(kMaterialTexels * material + kMaterialFactorTexels + 2u * slot);
  GpuTextureView v;
  v.uRow = imageLoad(uMaterials, at);
  v.vRow = imageLoad(uMaterials, at + 1);
  return v;
}

bool materialUnlit(GpuMaterial m) { return (uint(m.flags) & kMaterialUnlit) != 0u; }

struct Surface {
  vec3 position;
  vec3 geometricNormal;  // unit, facing the incoming ray
  vec3 shadingNormal;    // unit, same side as geometricNormal (normal map applied)
  vec2 uv0;
  vec2 uv1;
  vec4 color;    // COLOR_0, white without
  vec4 tangent;  // world xyz (not unit), w = +-1; w = 0: none
  // log2 of the uv extent of one world unit on the triangle: 0.5 log2(uv area / world area)
  float uvDensity;
  // log2 of the ray footprint's side in uv units (ray cones; kFinestLod without a cone)
  float textureLod;
  uint material;
  uint triangle;   // GpuTriangle index
  float extent;    // the largest magnitude the hit was computed from (ray offsets)
  bool frontFace;  // the ray hit the triangle's front (counter-clockwise) side
};

vec4 texel(GpuTexture t, int x, int y) {
  if ((t.flags & kTextureClampS) != 0u) x = clamp(x, 0, int(t.width) - 1);
  else if ((t.flags & kTextureMirrorS) != 0u) { int p = int(2u * t.width); x = ((x % p) + p) % p; if (x >= int(t.width)) x = p - 1 - x; }
  else x = ((x % int(t.width)) + int(t.width)) % int(t.width);
  if ((t.flags & kTextureClampT) != 0u) y = clamp(y, 0, int(t.height) - 1);
  else if ((t.flags & kTextureMirrorT) != 0u) { int p = int(2u * t.height); y = ((y % p) + p) % p; if (y >= int(t.height)) y = p - 1 - y; }
  else y = ((y % int(t.height)) + int(t.height)) % int(t.height);
  vec4 c = unpackUnorm4x8(imageLoad(uTexels, int(t.offset + uint(y) * t.width + uint(x))).r);
  if ((t.flags & kTextureSrgb) != 0u)
    c.rgb = vec3(srgbToLinear(c.r), srgbToLinear(c.g), srgbToLinear(c.b));
  return c;
}

// Level `level` of a texture's mip chain, as a texture of its own.
GpuTexture textureLevel(GpuTexture t, uint level) {
  for (uint i = 0u; i < level; ++i) {
    t.offset += t.width * t.height;
    t.width = max(t.width / 2u, 1u);
    t.height = max(t.height / 2u, 1u);
  }
  return t;
}

// Bilinear (or nearest) lookup in one level; linear values.
vec4 bilinear(GpuTexture t, vec2 uv) {
  vec2 p = uv * vec2(t.width, t.height) - 0.5;
  if ((t.flags & kTextureNearest) != 0u) return texel(t, int(floor(p.x + 0.5)), int(floor(p.y + 0.5)));
  ivec2 i = ivec2(floor(p));
  vec2 f = p - vec2(i);
  return mix(mix(texel(t, i.x, i.y), texel(t, i.x + 1, i.y), f.x),
             mix(texel(t, i.x, i.y + 1), texel(t, i.x + 1, i.y + 1), f.x), f.y);
}

// Trilinear lookup: lod is log2 of the footprint's side in uv units (kFinestLod: level 0);
// the level is lod + log2 of the texture's side, between 0 and its last.
const float kFinestLod = -64.0;
vec4 sampleTextureAt(int index, vec2 uv, float lod) {
  GpuTexture t = textureAt(index);
  uint levels = max(t.flags >> kTextureLevelShift, 1u);
  float level = lod + 0.5 * log2(float(t.width) * float(t.height));
  level = isnan(level) ? 0.0 : clamp(level, 0.0, float(levels - 1u));
  uint l0 = uint(level);
  GpuTexture a = textureLevel(t, l0);
  vec4 c = bilinear(a, uv);
  float f = level - float(l0);
  if (f > 0.0) c = mix(c, bilinear(textureLevel(a, 1u), uv), f);
  return c;
}

// A material's texture slot at UV sets (uv0, uv1), through its KHR_texture_transform;
// white when the slot has no texture.
// lod: log2 of the footprint's side in the mesh's uv units (the transform's scale is
// added here).
vec4 sampleMaterialTexture(uint material, uint slot, vec2 uv0, vec2 uv1, float lod) {
  if (!kUseTextures) return vec4(1.0);
  GpuTextureView v = textureViewAt(material, slot);
  int index = int(v.vRow.w);
  if (index < 0) return vec4(1.0);
  vec2 uv = v.uRow.w > 0.5 ? uv1 : uv0;
  uv = vec2(dot(v.uRow.xy, uv) + v.uRow.z, dot(v.vRow.xy, uv) + v.vRow.z);
  float det = abs(v.uRow.x * v.vRow.y - v.uRow.y * v.vRow.x);
  return sampleTextureAt(index, uv, lod + 0.5 * log2(max(det, 1e-20)));
}

vec4 surfaceTexture(Surface s, uint slot) {
  return sampleMaterialTexture(s.material, slot, s.uv0, s.uv1, s.textureLod);
}

vec3 toWorldNormal(GpuInstance inst, vec3 n) {
  return vec3(dot(inst.normalFromObject[0].xyz, n), dot(inst.normalFromObject[1].xyz, n),
              dot(inst.normalFromObject[2].xyz, n));
}

vec3 toWorldTangent(GpuInstance inst, vec3 t) {
  return vec3(dot(inst.tangentFromObject[0].xyz, t), dot(inst.tangentFromObject[1].xyz, t),
              dot(inst.tangentFromObject[2].xyz, t));
}

// The normal map's normal, n and t in world space (t may be unnormalized). Falls back to
// n where the frame is degenerate.
vec3 normalMapped(Surface s, vec3 n) {
  vec3 t = s.tangent.xyz - n * dot(n, s.tangent.xyz);
  float tLength = length(t);
  if (!(tLength > 1e-8)) return n;
  t /= tLength;
  vec3 b = cross(n, t) * s.tangent.w;
  vec3 m = surfaceTexture(s, kTextureSlotNormal).xyz * 2.0 - 1.0;
  float scale = materialAt(s.material).normalScale;
  vec3 mapped = m.x * scale * t + m.y * scale * b + m.z * n;
  float mappedLength = length(mapped);
  return mappedLength > 1e-8 && !isnan(mappedLength) ? mapped / mappedLength : n;
}

// coneWidth: the ray cone's width at the hit (0: none, textures at their finest level).
Surface resolveSurfaceWithCone(BvhHit hit, vec3 origin, vec3 dir, float coneWidth) {
  GpuInstance inst = instanceAt(hit.instance);
  Surface s;
  s.triangle = inst.firstTriangle + hit.primitive;
  GpuTriangle tri = triangleAt(s.triangle);
  GpuVertex a = vertexAt(tri.v0), b = vertexAt(tri.v1), c = vertexAt(tri.v2);
  float w = 1.0 - hit.u - hit.v;
  s.position = origin + hit.t * dir;
  // The intersection ran in object space on these vertices and the ray's origin.
  vec3 m = max(max(abs(a.position), abs(b.position)), abs(c.position));
  vec3 o = abs(origin);
  s.extent = max(max(m.x, max(m.y, m.z)) * inst.worldScale, max(o.x, max(o.y, o.z)));
  s.uv0 = w * vec2(a.u, a.v) + hit.u * vec2(b.u, b.v) + hit.v * vec2(c.u, c.v);
  s.uv1 = vec2(0.0);
  s.color = vec4(1.0);
  s.tangent = vec4(0.0);
  if (kUseVertexExtras && tri.vertexExtras != kNoVertexExtras) {
    GpuVertexExtras ea = vertexExtrasAt(tri.vertexExtras, tri.v0);
    GpuVertexExtras eb = vertexExtrasAt(tri.vertexExtras, tri.v1);
    GpuVertexExtras ec = vertexExtrasAt(tri.vertexExtras, tri.v2);
    s.uv1 = w * ea.uv1 + hit.u * eb.uv1 + hit.v * ec.uv1;
    s.color = w * ea.color + hit.u * eb.color + hit.v * ec.color;
    vec3 t = w * ea.tangent.xyz + hit.u * eb.tangent.xyz + hit.v * ec.tangent.xyz;
    s.tangent = vec4(toWorldTangent(inst, t), ea.tangent.w < 0.0 ? -1.0 : 1.0);
  }
  s.material = tri.material;
  vec2 du1 = vec2(b.u, b.v) - vec2(a.u, a.v), du2 = vec2(c.u, c.v) - vec2(a.u, a.v);
  vec3 e1 = toWorldTangent(inst, b.position - a.position);
  vec3 e2 = toWorldTangent(inst, c.position - a.position);
  s.uvDensity = 0.5 * log2(max(abs(du1.x * du2.y - du1.y * du2.x), 1e-30) /
                           max(length(cross(e1, e2)), 1e-30));
  s.textureLod = kFinestLod;
  // M^-T (e1 x e2) is the world normal of the glTF front face, mirrored transforms included.
  vec3 ng = normalize(toWorldNormal(inst, cross(b.position - a.position, c.position - a.position)));
  vec3 ns = toWorldNormal(inst, w * a.normal + hit.u * b.normal + hit.v * c.normal);
  float nsLength = length(ns);
  ns = nsLength > 1e-8 && !isnan(nsLength) ? ns / nsLength : ng;
  if (coneWidth > 0.0)  // the footprint grows as 1 / cos on a slanted surface
    s.textureLod = log2(coneWidth / max(abs(dot(ng, dir)) / length(dir), 1e-3)) + s.uvDensity;
  if (kUseTextures && kUseVertexExtras && s.tangent.w != 0.0) ns = normalMapped(s, ns);
  s.frontFace = dot(ng, dir) < 0.0;
  if (!s.frontFace) ng = -ng;
  if (dot(ns, ng) < 0.0) ns = -ns;
  s.geometricNormal = ng;
  s.shadingNormal = ns;
  return s;
}

Surface resolveSurface(BvhHit hit, vec3 origin, vec3 dir) {
  return resolveSurfaceWithCone(hit, origin, dir, 0.0);
}

// Base colour times COLOR_0 and the base colour texture, alpha included.
vec4 surfaceBaseColor(Surface s, GpuMaterial m) {
  return m.baseColor * s.color * surfaceTexture(s, kTextureSlotBaseColor);
}

BsdfParams surfaceBsdf(Surface s) {
  GpuMaterial m = materialAt(s.material);
  BsdfParams p;
  p.baseColor = surfaceBaseColor(s, m).rgb;
  vec4 mr = surfaceTexture(s, kTextureSlotMetallicRoughness);
  p.metallic = clamp(m.metallic * mr.b, 0.0, 1.0);
  p.roughness = clamp(m.roughness * mr.g, 0.0, 1.0);
  p.specular = clamp(m.specular, 0.0, 1.0);
  p.transmission = clamp(m.transmission, 0.0, 1.0);
  p.ior = m.ior;
  // A solid refracts: entering through the front face, leaving through the back. At ior 1
  // nothing bends: the thin wall's straight-through lobe is the same light.
  bool solid = (uint(m.flags) & kMaterialVolume) != 0u && p.transmission > 0.0 &&
               abs(m.ior - 1.0) > 1e-3;
  p.eta = solid ? (s.frontFace ? m.ior : 1.0 / m.ior) : 0.0;
  return p;
}

// Radiance leaving the surface toward the ray origin: front side only unless double-sided.
// Unlit materials show their base colour (KHR_materials_unlit).
vec3 surfaceEmission(Surface s) {
  GpuMaterial m = materialAt(s.material);
  if (!s.frontFace && (uint(m.flags) & kMaterialDoubleSided) == 0u) return vec3(0.0);
  if (materialUnlit(m)) return surfaceBaseColor(s, m).rgb;
  if (m.emissive == vec3(0.0)) return vec3(0.0);
  return m.emissive * surfaceTexture(s, kTextureSlotEmissive).rgb;
}

// Alpha at a candidate hit: MASK passes where alpha < alphaCutoff, BLEND with probability
// 1 - alpha, decided by a hash of the ray and the triangle (stochastic transparency: each
// sample's ray sees a surface of alpha a with probability a, so the mean is the blend).
bool alphaAcceptsHit(uint instance, uint primitive, float u, float v, vec3 origin, vec3 dir) {
  if (!kUseAlphaTest) return true;
  GpuTriangle tri = triangleAt(instanceFirstTriangle(instance) + primitive);
  GpuMaterial m = materialAt(tri.material);
  uint flags = uint(m.flags);
  if ((flags & (kMaterialAlphaMask | kMaterialAlphaBlend)) == 0u) return true;
  float w = 1.0 - u - v;
  vec2 uv0 = w * vertexUv(tri.v0) + u * vertexUv(tri.v1) + v * vertexUv(tri.v2);
  vec2 uv1 = vec2(0.0);
  float alpha = m.baseColor.a;
  if (kUseVertexExtras && tri.vertexExtras != kNoVertexExtras) {
    GpuVertexExtras a = vertexExtrasAt(tri.vertexExtras, tri.v0);
    GpuVertexExtras b = vertexExtrasAt(tri.vertexExtras, tri.v1);
    GpuVertexExtras c = vertexExtrasAt(tri.vertexExtras, tri.v2);
    uv1 = w * a.uv1 + u * b.uv1 + v * c.uv1;
    alpha *= w * a.color.a + u * b.color.a + v * c.color.a;
  }
  alpha *= sampleMaterialTexture(tri.material, kTextureSlotBaseColor, uv0, uv1, kFinestLod).a;
  if ((flags & kMaterialAlphaMask) != 0u) return alpha >= m.alphaCutoff;
  uint h = pcgHash(floatBitsToUint(origin.x) ^ pcgHash(floatBitsToUint(origin.y) ^
           pcgHash(floatBitsToUint(origin.z) ^ pcgHash(floatBitsToUint(dir.x) ^
           pcgHash(floatBitsToUint(dir.y) + 0x9e3779b9u * primitive + instance)))));
  return uintToUnitFloat(h) < alpha;
}

#define QL_BVH_ACCEPT_HIT(instance, primitive, u, v) \
  alphaAcceptsHit(instance, primitive, u, v, origin, dir)
#include "shared/bvh_traverse.h"
