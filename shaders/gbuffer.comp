#version 460
// The primary hit of each pixel's centre for the display filter: shading normal and distance
// (reprojection's disocclusion test, the a-trous filter's edges), base colour (the filter
// smooths irradiance, not texture) and whether it is an emitter. Display only: nothing here reaches
// the accumulation.
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require
#include "shared/scene_types.h"
#include "shared/bsdf.h"
#include "shared/tonemap.h"
#include "include/scene_access.glsl"
#include "include/filter_uniforms.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = QL_FILTER_BIND_GBUFFER, rgba32f) uniform writeonly image2D uGbuffer;
layout(binding = QL_FILTER_BIND_ALBEDO, rgba32f) uniform writeonly image2D uAlbedo;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(uGbuffer);
  if (any(greaterThanEqual(pixel, size))) return;
  vec2 ndc = (vec2(pixel) + 0.5) / vec2(size) * 2.0 - 1.0;
  GpuCamera cam = u.camera;
  vec3 dir = normalize(cam.forward + ndc.x * cam.tanHalfFovY * cam.aspect * cam.right -
                       ndc.y * cam.tanHalfFovY * cam.up);
  BvhHit hit;
  if (!traceClosest(cam.position, dir, 1e30, hit)) {
    imageStore(uGbuffer, pixel, vec4(0.0));
    imageStore(uAlbedo, pixel, vec4(1.0));
    return;
  }
  Surface s = resolveSurface(hit, cam.position, dir);
  imageStore(uGbuffer, pixel, vec4(s.shadingNormal, hit.t));
  // a = 0 marks emitters: the denoiser keeps them as they are and out of their neighbours.
  float emitter = surfaceEmission(s) != vec3(0.0) ? 0.0 : 1.0;
  imageStore(uAlbedo, pixel, vec4(max(surfaceBsdf(s).baseColor, vec3(0.01)), emitter));
}
