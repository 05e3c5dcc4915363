// Ray and hit lists of shaders/trace_rays.comp (the traversal-against-Embree
// benchmark, bench/traversal_vs_embree), shared by GLSL and C++. Both lists
// are 16-byte texel buffers: rays are read with texelFetch and hits written
// with imageStore, whole texels, which vectorize on lavapipe.
#ifndef QLIGHT_SHARED_TRACE_RAYS_H
#define QLIGHT_SHARED_TRACE_RAYS_H

#include "bindings.h"
#include "common.h"

QL_BEGIN

// 2 RGBA32F texels: (origin.xyz, tMax), (dir.xyz, 0). The ray counts hits
// with 0 < t < tMax, t along dir (which need not be unit length).
struct TraceRay {
  vec3 origin;
  float tMax;
  vec3 dir;
  float pad;
};
QL_CHECK_SIZE(TraceRay, 32);
QL_CONST uint kTraceRayTexels = 2u;

// 1 RGBA32UI texel: (t bits, instance, primitive, hit). A miss has hit = 0,
// t = -1 and both indices kBvhInvalidIndex; an any-hit ray reports only hit.
struct TraceHit {
  float t;
  uint instance;
  uint primitive;
  uint hit;
};
QL_CHECK_SIZE(TraceHit, 16);

struct TraceRaysPush {
  uint rayCount;
  uint pad0;
  uint pad1;
  uint pad2;
};
QL_CHECK_SIZE(TraceRaysPush, 16);

QL_END

#endif
