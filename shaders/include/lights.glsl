// Light selection (by power, from an inclusive CDF) and light sampling for
// next event estimation, plus the pdf of hitting a light by a scattered ray.
// The lights, kLightTexels texels each.
layout(binding = QL_BIND_LIGHTS, rgba32ui) uniform readonly restrict uimageBuffer uLights;

// Light i (a texel buffer for the reason in scene_access.glsl); unused fields are not fetched.
GpuLight lightAt(uint i) {
  int at = int(kLightTexels * i);
  uvec4 a = imageLoad(uLights, at), b = imageLoad(uLights, at + 1),
        c = imageLoad(uLights, at + 2), d = imageLoad(uLights, at + 3),
        e = imageLoad(uLights, at + 4);
  GpuLight l;
  l.position = uintBitsToFloat(a.xyz);
  l.type = a.w;
  l.edge1 = uintBitsToFloat(b.xyz);
  l.triangle = b.w;
  l.edge2 = uintBitsToFloat(c.xyz);
  l.area = uintBitsToFloat(c.w);
  l.emission = uintBitsToFloat(d.xyz);
  l.cosInner = uintBitsToFloat(d.w);
  l.cosOuter = uintBitsToFloat(e.x);
  l.range = uintBitsToFloat(e.y);
  l.flags = e.z;
  l.power = uintBitsToFloat(e.w);
  return l;
}
layout(binding = QL_BIND_LIGHT_CDF, r32f) uniform readonly restrict imageBuffer uLightCdf;
float lightCdfAt(uint i) { return imageLoad(uLightCdf, int(i)).x; }
layout(binding = QL_BIND_ENV_TEXELS, rgba32f) uniform readonly restrict imageBuffer uEnvTexels;
layout(binding = QL_BIND_ENV_CDF, r32f) uniform readonly restrict imageBuffer uEnvCdf;
#define QL_ENV_TEXEL_AT(i) imageLoad(uEnvTexels, int(i))
#define QL_ENV_CDF_AT(i) imageLoad(uEnvCdf, int(i)).x
#include "shared/environment.h"

struct LightSample {
  vec3 direction;  // unit, from the shading point to the light
  float distance;  // to the light point; infinite (1e30) for directional and sky
  vec3 radiance;   // arriving radiance (or intensity / d^2 for punctual lights)
  float pdf;       // solid-angle pdf including selection; 0: no sample
  bool delta;      // punctual or directional: cannot be hit by a scattered ray
};

uint selectLight(float u, uint count, out float selectPdf) {
  float total = lightCdfAt(count - 1u);
  float target = u * total;
  uint lo = 0u, hi = count - 1u;
  while (lo < hi) {
    uint mid = (lo + hi) >> 1u;
    if (lightCdfAt(mid) <= target) lo = mid + 1u; else hi = mid;
  }
  float below = lo > 0u ? lightCdfAt(lo - 1u) : 0.0;
  selectPdf = (lightCdfAt(lo) - below) / total;
  return lo;
}

float lightSelectPdf(uint index, uint count) {
  float below = index > 0u ? lightCdfAt(index - 1u) : 0.0;
  return (lightCdfAt(index) - below) / lightCdfAt(count - 1u);
}

vec3 triangleLightNormal(GpuLight l) {
  vec3 n = normalize(cross(l.edge1, l.edge2));
  return (l.flags & kLightMirrored) != 0u ? -n : n;
}

// Emission of an emissive triangle at barycentrics (b1, b2), texture included.
vec3 triangleLightRadiance(GpuLight l, vec2 b) {
  if (!kUseTextures) return l.emission;
  GpuTriangle tri = triangleAt(l.triangle);
  vec3 w = vec3(1.0 - b.x - b.y, b.x, b.y);
  vec2 uv0 = w.x * vertexUv(tri.v0) + w.y * vertexUv(tri.v1) + w.z * vertexUv(tri.v2);
  vec2 uv1 = vec2(0.0);
  if (kUseVertexExtras && tri.vertexExtras != kNoVertexExtras)
    uv1 = w.x * vertexExtrasAt(tri.vertexExtras, tri.v0).uv1 +
          w.y * vertexExtrasAt(tri.vertexExtras, tri.v1).uv1 +
          w.z * vertexExtrasAt(tri.vertexExtras, tri.v2).uv1;
  return l.emission * sampleMaterialTexture(tri.material, kTextureSlotEmissive, uv0, uv1, kFinestLod).rgb;
}

// Solid-angle pdf of sampling direction `dir` toward a point on triangle light `l`
// at distance `dist`, selection included (MIS for scattered rays that hit it).
float triangleLightPdf(GpuLight l, float selectPdf, vec3 dir, float dist) {
  float cosLight = abs(dot(triangleLightNormal(l), dir));
  return cosLight > 0.0 ? selectPdf * dist * dist / (l.area * cosLight) : 0.0;
}

bool skyHasMap(GpuLight l) { return kUseEnvironmentMap && (l.flags & kLightEnvironmentMap) != 0u; }

struct SkySeen {
  vec3 radiance;  // in the ray's direction
  float pdf;      // solid-angle pdf of NEE sampling that direction given its light, selection excluded
  uint light;     // the sky's light holding the direction (its tile's, with a map)
};

// The sky seen in world direction `dir`; `last` is the last light, a sky one.
SkySeen skySeenFrom(uint last, vec3 dir) {
  GpuLight l = lightAt(last);
  SkySeen s;
  if (skyHasMap(l)) {
    EnvironmentMap e = environmentMapHeader();
    EnvironmentTexel t = environmentLookup(e, dir);
    s.radiance = l.emission * t.radiance;
    s.pdf = t.pdf;
    s.light = last - (e.tilesX * e.tilesY - 1u) + t.tile;
  } else {
    s.radiance = l.emission;
    s.pdf = uniformSpherePdf();
    s.light = last;
  }
  return s;
}

// Samples a point or direction on light `index`, chosen with probability selectPdf.
LightSample sampleLight(vec3 x, vec2 u, uint index, float selectPdf) {
  LightSample s;
  s.pdf = 0.0;
  s.delta = false;
  s.distance = 1e30;
  s.radiance = vec3(0.0);
  s.direction = vec3(0.0, 0.0, 1.0);
  GpuLight l = lightAt(index);
  if (l.type == kLightTriangle) {
    vec3 bary = sampleTriangleBarycentrics(u);
    vec3 p = l.position + bary.y * l.edge1 + bary.z * l.edge2;
    vec3 d = p - x;
    float dist = length(d);
    if (!(dist > 0.0)) return s;
    s.direction = d / dist;
    s.distance = dist;
    float cosLight = dot(triangleLightNormal(l), -s.direction);
    if (cosLight <= 0.0 && (l.flags & kLightDoubleSided) == 0u) return s;
    s.radiance = triangleLightRadiance(l, bary.yz);
    s.pdf = triangleLightPdf(l, selectPdf, s.direction, dist);
  } else if (kUseNonTriangleLights && (l.type == kLightPoint || l.type == kLightSpot)) {
    vec3 d = l.position - x;
    float dist2 = dot(d, d);
    if (!(dist2 > 0.0)) return s;
    float dist = sqrt(dist2);
    s.direction = d / dist;
    s.distance = dist;
    float attenuation = 1.0 / dist2;
    if (l.range > 0.0) {  // KHR_lights_punctual's recommended smooth range window
      float r = dist / l.range;
      attenuation *= clamp(1.0 - r * r * r * r, 0.0, 1.0) * clamp(1.0 - r * r * r * r, 0.0, 1.0);
    }
    if (l.type == kLightSpot) {
      float cd = dot(l.edge1, -s.direction);
      float scale = 1.0 / max(0.001, l.cosInner - l.cosOuter);
      float a = clamp((cd - l.cosOuter) * scale, 0.0, 1.0);
      attenuation *= a * a;
    }
    s.radiance = l.emission * attenuation;
    s.pdf = selectPdf;
    s.delta = true;
  } else if (kUseNonTriangleLights && l.type == kLightDirectional) {
    s.direction = -l.edge1;
    s.radiance = l.emission;
    s.pdf = selectPdf;
    s.delta = true;
  } else if (kUseNonTriangleLights) {  // sky
    if (skyHasMap(l)) {
      EnvironmentSample e = sampleEnvironmentTile(environmentMapHeader(), l.triangle, u);
      s.direction = e.direction;
      s.radiance = l.emission * e.radiance;
      s.pdf = selectPdf * e.pdf;
    } else {
      s.direction = sampleUniformSphere(u);
      s.radiance = l.emission;
      s.pdf = selectPdf * uniformSpherePdf();
    }
  }
  return s;
}
