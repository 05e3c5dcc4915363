#version 460
// Traversal alone, on rays made by the CPU (bench/traversal_vs_embree traces
// the same list through Embree): one ray per invocation through qlight's own
// traversal, the hit written out for the agreement check. Specialized on the
// query, so each pipeline holds one traversal loop (as the trace pass folds
// its constant).
#extension GL_GOOGLE_include_directive : require
#include "shared/scene_types.h"
#include "shared/trace_rays.h"

layout(local_size_x = 64) in;
layout(constant_id = 3) const bool kAnyHit = false;  // ids 0..2 are the workgroup size

layout(binding = QL_BIND_BVH_NODES, rgba32f) uniform readonly restrict imageBuffer uBvhNodes;
layout(binding = QL_BIND_BVH_TRIS, rgba32f) uniform readonly restrict imageBuffer uBvhTris;
layout(binding = QL_BIND_BVH_INSTANCES, rgba32f) uniform readonly restrict imageBuffer uBvhInst;
#define QL_BVH_NODE(i) imageLoad(uBvhNodes, int(i))
#define QL_BVH_TRI(i) imageLoad(uBvhTris, int(i))
#define QL_BVH_INST(i) imageLoad(uBvhInst, int(i))
#include "shared/bvh_traverse.h"

layout(binding = QL_BIND_TRACE_RAYS) uniform samplerBuffer uRays;
layout(binding = QL_BIND_TRACE_HITS, rgba32ui) uniform writeonly uimageBuffer uHits;
layout(push_constant) uniform Push { TraceRaysPush pc; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= pc.rayCount) return;
  vec4 a = texelFetch(uRays, int(kTraceRayTexels * i));
  vec4 b = texelFetch(uRays, int(kTraceRayTexels * i + 1u));
  BvhHit h;
  bool found;
  if (kAnyHit) {
    found = traceAny(a.xyz, b.xyz, a.w);
    h.instance = kBvhInvalidIndex;
    h.primitive = kBvhInvalidIndex;
    h.t = -1.0;  // no distance: only whether something is in the way
  } else {
    found = traceClosest(a.xyz, b.xyz, a.w, h);
  }
  if (!found) {
    h.t = -1.0;
    h.instance = kBvhInvalidIndex;
    h.primitive = kBvhInvalidIndex;
  }
  imageStore(uHits, int(i), uvec4(floatBitsToUint(h.t), h.instance, h.primitive, found ? 1u : 0u));
}
