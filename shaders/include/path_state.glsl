// One path's state between the wavefront passes, kPathStateTexels RGBA32UI
// texels per path in a storage texel buffer (integer texels keep every bit
// pattern, including the NaN-shaped ones of packed indices, on any GPU). The
// texel of each field: kPathTexel* in shared/scene_types.h.
layout(binding = QL_BIND_PATH_STATE, rgba32ui) uniform uimageBuffer uPaths;

const uint kPathAlive = 1u;          // has an extension ray to trace / a hit to shade
const uint kPathShadowPending = 2u;  // a shadow ray waits for the next trace pass
const uint kPathEmitterHit = 4u;     // a scattered ray has reached an emitter
const uint kPathInvalid = 8u;        // a NaN/Inf appeared (the sample is dropped)

struct PathState {
  vec3 origin;
  uint pixel;
  vec3 dir;
  uint rng;
  vec3 throughput;
  float prevScatterPdf;  // pdf of the direction that led to the current hit (0: camera ray)
  vec3 radiance;
  uint flags;
  vec3 shadowOrigin;
  float shadowTMax;
  vec3 shadowDir;
  uint prevPoint;        // cache point of the previous vertex
  vec3 shadowContribution;
  uint prevEntry;        // its Q entry for the direction taken
  float hitT;            // < 0: the extension ray missed
  float hitU;
  float hitV;
  uint hitInstance;
  uint hitPrimitive;
  float shadowTarget;    // light-learning target if the shadow ray is unoccluded
  uint shadowPoint;      // where to record it (kNoCachePoint: nowhere)
  uint shadowLight;
  uint vertices;         // path length up to the first emitter reached (D&K)
  uint covered;          // vertices that found a cache point
  float coneWidth;       // the ray cone at the origin: its width (world units)
  float coneSpread;      // and its spread angle (radians), for texture filtering
  uint rays;
  uint shadowRays;
};

vec4 pathTexel(uint path, uint i) {
  return uintBitsToFloat(imageLoad(uPaths, int(path * kPathStateTexels + i)));
}
void setPathTexel(uint path, uint i, vec4 v) {
  imageStore(uPaths, int(path * kPathStateTexels + i), floatBitsToUint(v));
}

PathState loadPath(uint path) {
  PathState s;
  vec4 t;
  t = pathTexel(path, kPathTexelOrigin); s.origin = t.xyz; s.pixel = floatBitsToUint(t.w);
  t = pathTexel(path, kPathTexelDir); s.dir = t.xyz; s.rng = floatBitsToUint(t.w);
  t = pathTexel(path, kPathTexelThroughput); s.throughput = t.xyz; s.prevScatterPdf = t.w;
  t = pathTexel(path, kPathTexelRadianceFlags); s.radiance = t.xyz; s.flags = floatBitsToUint(t.w);
  t = pathTexel(path, kPathTexelShadowOrigin); s.shadowOrigin = t.xyz; s.shadowTMax = t.w;
  t = pathTexel(path, kPathTexelShadowDir); s.shadowDir = t.xyz; s.prevPoint = floatBitsToUint(t.w);
  t = pathTexel(path, kPathTexelShadowContribution);
  s.shadowContribution = t.xyz; s.prevEntry = floatBitsToUint(t.w);
  t = pathTexel(path, kPathTexelHit);
  s.hitT = t.x; s.hitU = t.y; s.hitV = t.z; s.hitInstance = floatBitsToUint(t.w);
  t = pathTexel(path, kPathTexelShadowLearning);
  s.hitPrimitive = floatBitsToUint(t.x); s.shadowTarget = t.y;
  s.shadowPoint = floatBitsToUint(t.z); s.shadowLight = floatBitsToUint(t.w);
  uvec4 c = floatBitsToUint(pathTexel(path, kPathTexelCounters));
  s.vertices = c.x & 0xffffu; s.covered = c.x >> 16u; s.rays = c.z; s.shadowRays = c.w;
  vec2 cone = unpackHalf2x16(c.y); s.coneWidth = cone.x; s.coneSpread = cone.y;
  return s;
}

void storePath(uint path, PathState s) {
  setPathTexel(path, kPathTexelOrigin, vec4(s.origin, uintBitsToFloat(s.pixel)));
  setPathTexel(path, kPathTexelDir, vec4(s.dir, uintBitsToFloat(s.rng)));
  setPathTexel(path, kPathTexelThroughput, vec4(s.throughput, s.prevScatterPdf));
  setPathTexel(path, kPathTexelRadianceFlags, vec4(s.radiance, uintBitsToFloat(s.flags)));
  setPathTexel(path, kPathTexelShadowOrigin, vec4(s.shadowOrigin, s.shadowTMax));
  setPathTexel(path, kPathTexelShadowDir, vec4(s.shadowDir, uintBitsToFloat(s.prevPoint)));
  setPathTexel(path, kPathTexelShadowContribution,
               vec4(s.shadowContribution, uintBitsToFloat(s.prevEntry)));
  setPathTexel(path, kPathTexelHit, vec4(s.hitT, s.hitU, s.hitV, uintBitsToFloat(s.hitInstance)));
  setPathTexel(path, kPathTexelShadowLearning,
               vec4(uintBitsToFloat(s.hitPrimitive), s.shadowTarget, uintBitsToFloat(s.shadowPoint),
                    uintBitsToFloat(s.shadowLight)));
  setPathTexel(path, kPathTexelCounters,
               uintBitsToFloat(uvec4(s.vertices | (s.covered << 16u),
                                     packHalf2x16(vec2(s.coneWidth, s.coneSpread)), s.rays,
                                     s.shadowRays)));
}
