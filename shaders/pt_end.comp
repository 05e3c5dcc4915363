#version 460
// Wavefront pass 4: adds each path's radiance to the accumulation image
// (rgb: sum, a: sample count) and its counters to the frame's stats; with
// learning from returns, the path's open records get their targets.
#extension GL_GOOGLE_include_directive : require
#include "include/path_common.glsl"
#include "include/learning_returns.glsl"

layout(binding = QL_BIND_ACCUM, rgba32f) uniform image2D uAccum;
layout(binding = QL_BIND_STATS) buffer Stats { uint stats[]; };

void addStat(uint index, uint value) {
  uint total = subgroupAdd(value);
  if (subgroupElect() && total > 0u) atomicAdd(stats[index], total);
}

void main() {
  uint path = gl_GlobalInvocationID.x;
  bool inside = path < pc.pathCount;
  uint flags = 0u;
  uvec4 counters = uvec4(0u);
  uint invalid = 0u;
  if (inside) {
    vec4 radianceFlags = pathTexel(path, kPathTexelRadianceFlags);
    flags = floatBitsToUint(radianceFlags.w);
    counters = floatBitsToUint(pathTexel(path, kPathTexelCounters));
    vec3 radiance = radianceFlags.xyz;
    if (learningFromReturns()) flushReturnRecords(path, flags, luminance(radiance));
    if (any(isnan(radiance)) || any(isinf(radiance))) {
      radiance = vec3(0.0);
      invalid = 1u;
    }
    ivec2 pixel = ivec2(path % frame.resolution.x, path / frame.resolution.x);
    imageStore(uAccum, pixel, imageLoad(uAccum, pixel) + vec4(radiance, 1.0));
  }
  addStat(kStatRays, counters.z & 0xffffu);
  addStat(kStatShadowRays, counters.z >> 16u);
  addStat(kStatPaths, inside ? 1u : 0u);
  addStat(kStatEmitterHits, (flags & kPathEmitterHit) != 0u ? 1u : 0u);
  addStat(kStatPathVertices, counters.x & 0xffffu);
  addStat(kStatInvalidSamples, invalid);
  addStat(kStatCoveredVertices, counters.x >> 16u);
}
