#version 460
// Temporal blending for animated scenes: instead of discarding the
// accumulated samples when lights move, weight them down by `factor`, so the
// image keeps an exponentially fading history (a little lag, far less noise).
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require
#include "shared/accum_decay.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = QL_ACCUM_DECAY_BIND_ACCUM, rgba32f) uniform image2D uAccum;
layout(push_constant, scalar) uniform Push { AccumDecayPush pc; };

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= int(pc.width) || p.y >= int(pc.height)) return;
  imageStore(uAccum, p, imageLoad(uAccum, p) * pc.factor);
}
