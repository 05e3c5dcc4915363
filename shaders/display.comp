#version 460
// Shows the path tracer's accumulation: mean radiance (rgb / sample count),
// exposed and tonemapped to display sRGB, stored as RGBA8 for the blit to the swapchain.
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require
#include "shared/tonemap.h"
#include "../engine/ui/display_types.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = QL_DISPLAY_BIND_ACCUM, rgba32f) uniform readonly image2D uAccum;
layout(binding = QL_DISPLAY_BIND_OUTPUT, rgba8) uniform writeonly image2D uDisplay;
layout(push_constant, scalar) uniform Push { DisplayPush pc; };

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, imageSize(uDisplay)))) return;
  vec4 sum = imageLoad(uAccum, pixel);
  vec3 mean = sum.a > 0.0 ? sum.rgb / sum.a : vec3(0.0);
  vec3 display = displayFromLinear(mean, pc.exposure, pc.tonemap);
  if (pc.encodeSrgb == 0u)
    display = vec3(srgbToLinear(display.r), srgbToLinear(display.g), srgbToLinear(display.b));
  imageStore(uDisplay, pixel, vec4(display, 1.0));
}
