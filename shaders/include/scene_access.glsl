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

layout(binding = QL_BIND_TRIANGLES) uniform usamplerBuffer uTriangles;  // 2 texels each
layout(binding = QL_BIND_VERTICES) uniform samplerBuffer uVertices;     // 2 texels each
layout(binding = QL_BIND_INSTANCES, scalar) readonly buffer Instances { GpuInstance instances[]; };
layout(binding = QL_BIND_MATERIALS) uniform samplerBuffer uMaterials;   // 4 texels each
layout(binding = QL_BIND_TEXTURES, scalar) readonly buffer Textures { GpuTexture textures[]; };
layout(binding = QL_BIND_TEXELS) uniform usamplerBuffer uTexels;

GpuTriangle triangleAt(uint i) {
  uvec4 a = texelFetch(uTriangles, int(2u * i));
  GpuTriangle t;
  t.v0 = a.x;
  t.v1 = a.y;
  t.v2 = a.z;
  t.material = a.w;
  t.light = texelFetch(uTriangles, int(2u * i + 1u)).x;
  t.pad0 = t.pad1 = t.pad2 = 0u;
  return t;
}

GpuVertex vertexAt(uint i) {
  vec4 a = texelFetch(uVertices, int(2u * i));
  vec4 b = texelFetch(uVertices, int(2u * i + 1u));
  GpuVertex v;
  v.position = a.xyz;
  v.u = a.w;
  v.normal = b.xyz;
  v.v = b.w;
  return v;
}

vec2 vertexUv(uint i) {
  return vec2(texelFetch(uVertices, int(2u * i)).w, texelFetch(uVertices, int(2u * i + 1u)).w);
}

GpuMaterial materialAt(uint i) {
  vec4 a = texelFetch(uMaterials, int(4u * i));
  vec4 b = texelFetch(uMaterials, int(4u * i + 1u));
  vec4 c = texelFetch(uMaterials, int(4u * i + 2u));
  vec4 d = texelFetch(uMaterials, int(4u * i + 3u));
  GpuMaterial m;
  m.baseColor = a;
  m.emissive = b.xyz;
  m.metallic = b.w;
  m.roughness = c.x;
  m.specular = c.y;
  m.flags = c.z;
  m.pad0 = 0.0;
  m.baseColorTexture = d.x;
  m.metallicRoughnessTexture = d.y;
  m.emissiveTexture = d.z;
  m.pad1 = 0.0;
  return m;
}

struct Surface {
  vec3 position;
  vec3 geometricNormal;  // unit, facing the incoming ray
  vec3 shadingNormal;    // unit, same side as geometricNormal
  vec2 uv;
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
  GpuTriangle tri = triangleAt(s.triangle);
  GpuVertex a = vertexAt(tri.v0), b = vertexAt(tri.v1), c = vertexAt(tri.v2);
  float w = 1.0 - hit.u - hit.v;
  s.position = origin + hit.t * dir;
  // The intersection ran in object space on these vertices and the ray's origin.
  vec3 m = max(max(abs(a.position), abs(b.position)), abs(c.position));
  vec3 o = abs(origin);
  s.extent = max(max(m.x, max(m.y, m.z)) * inst.worldScale, max(o.x, max(o.y, o.z)));
  s.uv = w * vec2(a.u, a.v) + hit.u * vec2(b.u, b.v) + hit.v * vec2(c.u, c.v);
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
  GpuMaterial m = materialAt(s.material);
  BsdfParams p;
  p.baseColor = m.baseColor.rgb * sampleTexture(int(m.baseColorTexture), s.uv).rgb;
  vec4 mr = sampleTexture(int(m.metallicRoughnessTexture), s.uv);
  p.metallic = clamp(m.metallic * mr.b, 0.0, 1.0);
  p.roughness = clamp(m.roughness * mr.g, 0.0, 1.0);
  p.specular = clamp(m.specular, 0.0, 1.0);
  return p;
}

// Radiance leaving the surface toward the ray origin: front side only unless double-sided.
vec3 surfaceEmission(Surface s) {
  GpuMaterial m = materialAt(s.material);
  if (!s.frontFace && (uint(m.flags) & kMaterialDoubleSided) == 0u) return vec3(0.0);
  if (m.emissive == vec3(0.0)) return vec3(0.0);
  return m.emissive * sampleTexture(int(m.emissiveTexture), s.uv).rgb;
}
