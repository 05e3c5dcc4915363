// Scene buffers of the path tracer and the hit -> surface resolution.
// Included by the path tracing and guiding passes after the shared headers.
#include "include/features.glsl"

layout(binding = QL_BIND_BVH_NODES) uniform samplerBuffer uBvhNodes;
layout(binding = QL_BIND_BVH_TRIS) uniform samplerBuffer uBvhTris;
layout(binding = QL_BIND_BVH_INSTANCES) uniform samplerBuffer uBvhInstances;
#define QL_BVH_NODE(i) texelFetch(uBvhNodes, int(i))
#define QL_BVH_TRI(i) texelFetch(uBvhTris, int(i))
#define QL_BVH_INST(i) texelFetch(uBvhInstances, int(i))
#include "shared/bvh_traverse.h"

layout(binding = QL_BIND_TRIANGLES, scalar) readonly buffer Triangles { GpuTriangle triangles[]; };
layout(binding = QL_BIND_VERTICES, scalar) readonly buffer Vertices { GpuVertex vertices[]; };
layout(binding = QL_BIND_INSTANCES, scalar) readonly buffer Instances { GpuInstance instances[]; };
layout(binding = QL_BIND_MATERIALS, scalar) readonly buffer Materials { GpuMaterial materials[]; };
layout(binding = QL_BIND_TEXTURES, scalar) readonly buffer Textures { GpuTexture textures[]; };
layout(binding = QL_BIND_TEXELS) uniform usamplerBuffer uTexels;

struct Surface {
  vec3 position;
  vec3 geometricNormal;  // unit, facing the incoming ray
  vec3 shadingNormal;    // unit, same side as geometricNormal
  vec2 uv;
  uint material;
  uint triangle;   // GpuTriangle index
  bool frontFace;  // the ray hit the triangle's front (counter-clockwise) side
};

vec4 texel(GpuTexture t, int x, int y) {
  if ((t.flags & kTextureClampS) != 0u) x = clamp(x, 0, int(t.width) - 1);
  else if ((t.flags & kTextureMirrorS) != 0u) { int p = int(2u * t.width); x = ((x % p) + p) % p; if (x >= int(t.width)) x = p - 1 - x; }
  else x = ((x % int(t.width)) + int(t.width)) % int(t.width);
  if ((t.flags & kTextureClampT) != 0u) y = clamp(y, 0, int(t.height) - 1);
  else if ((t.flags & kTextureMirrorT) != 0u) { int p = int(2u * t.height); y = ((y % p) + p) % p; if (y >= int(t.height)) y = p - 1 - y; }
  else y = ((y % int(t.height)) + int(t.height)) % int(t.height);
  vec4 c = unpackUnorm4x8(texelFetch(uTexels, int(t.offset + uint(y) * t.width + uint(x))).r);
  if ((t.flags & kTextureSrgb) != 0u)
    c.rgb = vec3(srgbToLinear(c.r), srgbToLinear(c.g), srgbToLinear(c.b));
  return c;
}

// Bilinear (or nearest) lookup without mipmaps; linear values.
vec4 sampleTexture(int index, vec2 uv) {
  if (!kUseTextures || index < 0) return vec4(1.0);
  GpuTexture t = textures[index];
  vec2 p = uv * vec2(t.width, t.height) - 0.5;
  if ((t.flags & kTextureNearest) != 0u) return texel(t, int(floor(p.x + 0.5)), int(floor(p.y + 0.5)));
  ivec2 i = ivec2(floor(p));
  vec2 f = p - vec2(i);
  return mix(mix(texel(t, i.x, i.y), texel(t, i.x + 1, i.y), f.x),
             mix(texel(t, i.x, i.y + 1), texel(t, i.x + 1, i.y + 1), f.x), f.y);
}

vec3 toWorldNormal(GpuInstance inst, vec3 n) {
  return vec3(dot(inst.normalFromObject[0].xyz, n), dot(inst.normalFromObject[1].xyz, n),
              dot(inst.normalFromObject[2].xyz, n));
}

Surface resolveSurface(BvhHit hit, vec3 origin, vec3 dir) {
  GpuInstance inst = instances[hit.instance];
  Surface s;
  s.triangle = inst.firstTriangle + hit.primitive;
  GpuTriangle tri = triangles[s.triangle];
  GpuVertex a = vertices[tri.v0], b = vertices[tri.v1], c = vertices[tri.v2];
  float w = 1.0 - hit.u - hit.v;
  s.position = origin + hit.t * dir;
  s.uv = w * a.uv + hit.u * b.uv + hit.v * c.uv;
  s.material = tri.material;
  // M^-T (e1 x e2) is the world normal of the glTF front face, mirrored transforms included.
  vec3 ng = normalize(toWorldNormal(inst, cross(b.position - a.position, c.position - a.position)));
  vec3 ns = toWorldNormal(inst, w * a.normal + hit.u * b.normal + hit.v * c.normal);
  float nsLength = length(ns);
  ns = nsLength > 1e-8 && !isnan(nsLength) ? ns / nsLength : ng;
  s.frontFace = dot(ng, dir) < 0.0;
  if (!s.frontFace) ng = -ng;
  if (dot(ns, ng) < 0.0) ns = -ns;
  s.geometricNormal = ng;
  s.shadingNormal = ns;
  return s;
}

BsdfParams surfaceBsdf(Surface s) {
  GpuMaterial m = materials[s.material];
  BsdfParams p;
  p.baseColor = m.baseColor.rgb * sampleTexture(m.baseColorTexture, s.uv).rgb;
  vec4 mr = sampleTexture(m.metallicRoughnessTexture, s.uv);
  p.metallic = clamp(m.metallic * mr.b, 0.0, 1.0);
  p.roughness = clamp(m.roughness * mr.g, 0.0, 1.0);
  p.specular = clamp(m.specular, 0.0, 1.0);
  return p;
}

// Radiance leaving the surface toward the ray origin: front side only unless double-sided.
vec3 surfaceEmission(Surface s) {
  GpuMaterial m = materials[s.material];
  if (!s.frontFace && (m.flags & kMaterialDoubleSided) == 0u) return vec3(0.0);
  if (m.emissive == vec3(0.0)) return vec3(0.0);
  return m.emissive * sampleTexture(m.emissiveTexture, s.uv).rgb;
}
