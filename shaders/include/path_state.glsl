// One path's state between the wavefront passes, kPathStateTexels RGBA32UI
// texels per path in a storage texel buffer (integer texels keep every bit
// pattern, including the NaN-shaped ones of packed indices, on any GPU). The
// texel of each field: kPathTexel* in shared/scene_types.h.
layout(binding = QL_BIND_PATH_STATE, rgba32ui) uniform uimageBuffer uPaths;

const uint kPathAlive = 1u;          // has an extension ray to trace / a hit to shade
const uint kPathEmitterHit = 4u;     // a scattered ray has reached an emitter
const uint kPathInvalid = 8u;        // a NaN/Inf appeared (the sample is dropped)

struct PathState {
  vec3 origin;
  uint prevPoint;        // cache point of the previous vertex
  vec3 dir;
  uint rng;
  vec3 throughput;
  float prevScatterPdf;  // pdf of the direction that led to the current hit (0: camera ray)
  vec3 radiance;
  uint flags;
  uint prevEntry;        // its Q entry for the direction taken
  float hitT;            // < 0: the extension ray missed
  float hitU;
  float hitV;
  uint hitInstance;
  uint hitPrimitive;
  uint vertices;         // path length up to the first emitter reached (D&K)
  uint covered;          // vertices that found a cache point
  float coneWidth;       // the ray cone at the origin: its width (world units)
  float coneSpread;      // and its spread angle (radians), for texture filtering
  uint rays;             // up to 65535 each (2 a bounce at most)
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
  t = pathTexel(path, kPathTexelOrigin); s.origin = t.xyz; s.prevPoint = floatBitsToUint(t.w);
  t = pathTexel(path, kPathTexelDir); s.dir = t.xyz; s.rng = floatBitsToUint(t.w);
  t = pathTexel(path, kPathTexelThroughput); s.throughput = t.xyz; s.prevScatterPdf = t.w;
  t = pathTexel(path, kPathTexelRadianceFlags); s.radiance = t.xyz; s.flags = floatBitsToUint(t.w);
  if (!kTraceInShade) {
    t = pathTexel(path, kPathTexelHit);
    s.hitT = t.x; s.hitU = t.y; s.hitV = t.z; s.hitInstance = floatBitsToUint(t.w);
    s.hitPrimitive = floatBitsToUint(pathTexel(path, kPathTexelHitPrimitive).x);
  }
  uvec4 c = floatBitsToUint(pathTexel(path, kPathTexelCounters));
  s.vertices = c.x & 0xffffu; s.covered = c.x >> 16u;
  s.rays = c.z & 0xffffu; s.shadowRays = c.z >> 16u; s.prevEntry = c.w;
  vec2 cone = unpackHalf2x16(c.y); s.coneWidth = cone.x; s.coneSpread = cone.y;
  return s;
}

// Everything but the hit, which only the trace pass writes (setHit).
void storePath(uint path, PathState s) {
  setPathTexel(path, kPathTexelOrigin, vec4(s.origin, uintBitsToFloat(s.prevPoint)));
  setPathTexel(path, kPathTexelDir, vec4(s.dir, uintBitsToFloat(s.rng)));
  setPathTexel(path, kPathTexelThroughput, vec4(s.throughput, s.prevScatterPdf));
  setPathTexel(path, kPathTexelRadianceFlags, vec4(s.radiance, uintBitsToFloat(s.flags)));
  setPathTexel(path, kPathTexelCounters,
               uintBitsToFloat(uvec4(s.vertices | (s.covered << 16u),
                                     packHalf2x16(vec2(s.coneWidth, s.coneSpread)),
                                     s.rays | (s.shadowRays << 16u), s.prevEntry)));
}

void setHit(uint path, float t, float u, float v, uint instance, uint primitive) {
  setPathTexel(path, kPathTexelHit, vec4(t, u, v, uintBitsToFloat(instance)));
  setPathTexel(path, kPathTexelHitPrimitive, uintBitsToFloat(uvec4(primitive, 0u, 0u, 0u)));
}
