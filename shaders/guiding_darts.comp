#version 460
// Darts (van Mastrigt 5.1): light paths leave the lights; every surface they
// land on is a candidate cache point, with its ambient occlusion for the
// Poisson-disk variant. The CPU accepts candidates by rejection distance.
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require
#include "shared/scene_types.h"
#include "shared/guiding_types.h"
#include "shared/random.h"
#include "shared/sampling.h"
#include "shared/bsdf.h"
#include "shared/tonemap.h"
#include "shared/ray_offset.h"
#include "include/scene_access.glsl"
#include "include/lights.glsl"

layout(local_size_x = 64) in;
// Each path's bounce has its own slot (unwritten slots keep the NaN fill), so
// the candidates, and the points accepted from them, do not depend on timing.
layout(binding = QL_BIND_DART_CANDIDATES, scalar) writeonly buffer Candidates { vec4 candidates[]; };
layout(push_constant, scalar) uniform Push { DartsPush pc; };

void emit(uint slot, vec3 p, vec3 n, float ao) {
  candidates[2u * slot] = vec4(p, ao);
  candidates[2u * slot + 1u] = vec4(n, 0.0);
}

// Share of short rays around n that hit something within the AO radius.
float occlusion(vec3 p, vec3 n, inout Rng rng) {
  if (pc.aoRays == 0u) return 0.0;
  TangentFrame f = frameFromNormal(n);
  uint hits = 0u;
  for (uint i = 0u; i < pc.aoRays; ++i) {
    vec3 d = worldFromLocal(f, sampleCosineHemisphere(rngNext2(rng)));
    if (traceAny(p, d, pc.aoRadius)) ++hits;
  }
  return float(hits) / float(pc.aoRays);
}

void main() {
  uint id = gl_GlobalInvocationID.x;
  if (id >= pc.pathCount || pc.lightCount == 0u) return;
  Rng rng = rngSeed(id, pc.seed, 0x5eedu);
  float selectPdf;
  GpuLight l = lightAt(selectLight(rngNextFloat(rng), pc.lightCount, selectPdf));
  vec3 origin, dir;
  if (l.type == kLightTriangle) {
    vec3 b = sampleTriangleBarycentrics(rngNext2(rng));
    vec3 n = triangleLightNormal(l);
    if ((l.flags & kLightDoubleSided) != 0u && rngNextFloat(rng) < 0.5) n = -n;
    vec3 extent = abs(l.position) + abs(l.edge1) + abs(l.edge2);
    origin = offsetRayOriginFrom(l.position + b.y * l.edge1 + b.z * l.edge2, n,
                                 max(extent.x, max(extent.y, extent.z)));
    dir = worldFromLocal(frameFromNormal(n), sampleCosineHemisphere(rngNext2(rng)));
  } else if (l.type == kLightPoint || l.type == kLightSpot) {
    origin = l.position;
    dir = sampleUniformSphere(rngNext2(rng));
  } else {  // directional or sky (from its tile): enter the scene's bounding sphere through a disk
    if (l.type == kLightDirectional) dir = l.edge1;
    else if (skyHasMap(l))
      dir = -sampleEnvironmentTile(environmentMapHeader(), l.triangle, rngNext2(rng)).direction;
    else dir = -sampleUniformSphere(rngNext2(rng));
    TangentFrame f = frameFromNormal(dir);
    vec2 disk = sampleConcentricDisk(rngNext2(rng)) * pc.sceneRadius;
    origin = pc.sceneCenter - 2.0 * pc.sceneRadius * dir + disk.x * f.tangent + disk.y * f.bitangent;
  }
  for (uint bounce = 0u; bounce < pc.maxBounces; ++bounce) {
    BvhHit hit;
    if (!traceClosest(origin, dir, 1e30, hit)) break;
    Surface s = resolveSurface(hit, origin, dir);
    vec3 p = offsetRayOriginFrom(s.position, s.geometricNormal, s.extent);
    emit(id * pc.maxBounces + bounce, s.position, s.geometricNormal, occlusion(p, s.geometricNormal, rng));
    dir = worldFromLocal(frameFromNormal(s.geometricNormal), sampleCosineHemisphere(rngNext2(rng)));
    origin = p;
  }
}
