#version 460
// Reuses the last frame's displayed image when the accumulation restarts (the camera moved):
// each pixel's primary hit is projected into the last frame's camera, and where the surface
// there is the same (distance within 5%, normals within ~25 degrees) its colour carries over
// with at most historyMax frames of weight; elsewhere (disoccluded) the pixel starts afresh.
// While the accumulation goes on, the history it started from fades out (historyKeep per
// frame), so a still image converges to the unbiased accumulation. Display only.
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require
#include "include/filter_uniforms.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = QL_FILTER_BIND_ACCUM, rgba32f) uniform readonly image2D uAccum;
layout(binding = QL_FILTER_BIND_GBUFFER, rgba32f) uniform readonly image2D uGbuffer;
layout(binding = QL_FILTER_BIND_PREV_GBUFFER, rgba32f) uniform readonly image2D uPrevGbuffer;
layout(binding = QL_FILTER_BIND_PREV_OUTPUT, rgba32f) uniform readonly image2D uPrevOutput;
layout(binding = QL_FILTER_BIND_HISTORY, rgba32f) uniform image2D uHistory;
layout(binding = QL_FILTER_BIND_OUTPUT, rgba32f) uniform writeonly image2D uOutput;

// The last frame's colour and weight of the surface this pixel sees, if it was visible.
vec4 reprojected(ivec2 pixel, ivec2 size) {
  vec4 g = imageLoad(uGbuffer, pixel);
  if (g.w <= 0.0) return vec4(0.0);
  GpuCamera cam = u.camera, prev = u.previousCamera;
  vec2 ndc = (vec2(pixel) + 0.5) / vec2(size) * 2.0 - 1.0;
  vec3 dir = normalize(cam.forward + ndc.x * cam.tanHalfFovY * cam.aspect * cam.right -
                       ndc.y * cam.tanHalfFovY * cam.up);
  vec3 world = cam.position + g.w * dir;
  vec3 d = world - prev.position;
  float z = dot(d, prev.forward);
  if (z <= 1e-6) return vec4(0.0);
  vec2 p = vec2(dot(d, prev.right) / (z * prev.tanHalfFovY * prev.aspect),
                -dot(d, prev.up) / (z * prev.tanHalfFovY));
  ivec2 q = ivec2(floor((p * 0.5 + 0.5) * vec2(size)));
  if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) return vec4(0.0);
  vec4 pg = imageLoad(uPrevGbuffer, q);
  float distance = length(d);
  if (pg.w <= 0.0 || abs(pg.w - distance) > 0.05 * distance || dot(pg.xyz, g.xyz) < 0.9)
    return vec4(0.0);
  vec4 h = imageLoad(uPrevOutput, q);
  if (!(h.a > 0.0)) return vec4(0.0);
  return vec4(h.rgb / h.a, min(h.a, u.historyMax));
}

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(uOutput);
  if (any(greaterThanEqual(pixel, size))) return;
  vec4 history;
  if (u.restarted != 0u)
    history = u.reproject != 0u ? reprojected(pixel, size) : vec4(0.0);
  else
    history = imageLoad(uHistory, pixel) * vec4(1.0, 1.0, 1.0, u.historyKeep);
  imageStore(uHistory, pixel, history);
  vec4 acc = imageLoad(uAccum, pixel);  // rgb sum, a count
  imageStore(uOutput, pixel, vec4(history.rgb * history.a + acc.rgb, history.a + acc.a));
}
