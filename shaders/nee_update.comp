#version 460
// The learned NEE probability's pass (shared/guiding_types.h, neeProbabilityOf), one thread
// per point: the frame's shadow-ray counts join the running ones, which age with tracking's
// forgetting and stop at kNeeWindow rays, so a point's probability follows a light that
// moves into or out of its view.
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require
#include "shared/guiding_types.h"

layout(local_size_x = QL_NEE_UPDATE_GROUP_SIZE) in;
layout(binding = QL_NEE_UPDATE_BIND_COUNTS, scalar) buffer NeeCounts { uint neeCounts[]; };
layout(push_constant, scalar) uniform Push { NeeUpdatePush pc; };

void main() {
  uint point = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x +
               gl_LocalInvocationID.x;
  if (point >= pc.rowCount) return;
  uint w = kNeeWordsPerPoint * point;
  float rays = uintBitsToFloat(neeCounts[w + 2u]) * pc.kept + float(neeCounts[w]);
  float unoccluded = uintBitsToFloat(neeCounts[w + 3u]) * pc.kept + float(neeCounts[w + 1u]);
  if (rays > kNeeWindow) {
    unoccluded *= kNeeWindow / rays;
    rays = kNeeWindow;
  }
  neeCounts[w] = 0u;
  neeCounts[w + 1u] = 0u;
  neeCounts[w + 2u] = floatBitsToUint(rays);
  neeCounts[w + 3u] = floatBitsToUint(unoccluded);
}
