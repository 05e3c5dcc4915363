#version 460
// One iteration of the edge-aware a-trous wavelet filter (Dammertz et al. 2010) on the
// displayed image: a 5x5 B3-spline kernel with holes of `step` pixels, each tap weighted by
// how alike its primary hit is (normal, distance, base colour) and its brightness. The first
// iteration divides by the base colour and the last multiplies it back, so texture and
// material edges stay sharp. Input: rgb sum, a weight; the last output too (a = 1), the
// ones between carry the colour and the samples. Display only.
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require
#include "../engine/ui/display_filter_types.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = QL_ATROUS_BIND_INPUT, rgba32f) uniform readonly image2D uInput;
layout(binding = QL_ATROUS_BIND_OUTPUT, rgba32f) uniform writeonly image2D uOutput;
layout(binding = QL_FILTER_BIND_GBUFFER, rgba32f) uniform readonly image2D uGbuffer;
layout(binding = QL_FILTER_BIND_ALBEDO, rgba32f) uniform readonly image2D uAlbedo;
layout(push_constant, scalar) uniform Push { AtrousPush pc; };

float luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }

// Samples behind a pixel: the first pass's input has them as its weight (rgb sum, a weight),
// the later passes carry them in alpha (rgb the filtered colour).
float samplesAt(ivec2 p) { return imageLoad(uInput, p).a; }

vec3 colourAt(ivec2 p) {
  vec4 v = imageLoad(uInput, p);
  if (pc.first == 0u) return v.rgb;
  vec3 c = v.a > 0.0 ? v.rgb / v.a : vec3(0.0);
  // A firefly would print the kernel's holes into its neighbours: above what the display
  // shows as white it adds nothing visible, so it is scaled down to that first (emitters,
  // a = 0, are kept out of the filter as they are).
  vec4 albedo = imageLoad(uAlbedo, p);
  float l = luminance(c);
  if (albedo.a != 0.0 && l > pc.maxLuminance) c *= pc.maxLuminance / l;
  return c / albedo.rgb;
}

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(uOutput);
  if (any(greaterThanEqual(pixel, size))) return;
  const float kernel[3] = float[3](3.0 / 8.0, 1.0 / 4.0, 1.0 / 16.0);
  vec3 c0 = colourAt(pixel);
  vec4 g0 = imageLoad(uGbuffer, pixel);
  vec4 albedo0 = imageLoad(uAlbedo, pixel);
  vec3 a0 = albedo0.rgb;
  if (albedo0.a == 0.0) {  // an emitter: its radiance is exact, and far from its neighbours'
    imageStore(uOutput, pixel, vec4(pc.last != 0u ? c0 * a0 : c0, pc.last != 0u ? 1.0 : 1e6));
    return;
  }
  float l0 = luminance(c0);
  // Brightness edges stop the filter, but at a few samples a pixel's brightness is mostly
  // noise: the tolerance widens as 1 / sqrt(samples).
  float samples = max(samplesAt(pixel), 1e-3);
  float sigma = pc.colourSigma * max(1.0, 4.0 / sqrt(samples));
  // Depths differing by 2% per step of the holes weigh 1/e (the centre's, for every tap).
  float depthScale = 1.0 / (0.02 * g0.w * float(pc.step) + 1e-4);
  vec3 sum = vec3(0.0);
  float weights = 0.0;
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -2; dx <= 2; ++dx) {
      ivec2 q = pixel + pc.step * ivec2(dx, dy);
      if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
      vec3 c = colourAt(q);
      vec4 g = imageLoad(uGbuffer, q);
      vec4 albedo = imageLoad(uAlbedo, q);
      if (albedo.a == 0.0) continue;  // emitters stay out of their neighbours
      vec3 a = albedo.rgb;
      float w = kernel[abs(dx)] * kernel[abs(dy)];
      // The edge-stopping factors multiply: their exponents add up to one exp (lavapipe
      // evaluates exp and pow as polynomials on every lane, so each one saved counts).
      float l = luminance(c);
      float exponent = -length(a0 - a) * 10.0 - abs(l0 - l) / (sigma * (0.5 * (l0 + l)) + 1e-4);
      if (g0.w > 0.0 && g.w > 0.0) {
        float n = max(dot(g0.xyz, g.xyz), 0.0);  // n^64 by squaring
        n *= n;
        n *= n;
        n *= n;
        n *= n;
        n *= n;
        n *= n;
        w *= n;
        exponent -= abs(g0.w - g.w) * depthScale;
      } else if ((g0.w > 0.0) != (g.w > 0.0)) {
        w = 0.0;  // a surface and the background do not mix
      }
      w *= exp(exponent);
      sum += w * c;
      weights += w;
    }
  vec3 filtered = weights > 0.0 ? sum / weights : c0;
  if (pc.last != 0u) filtered *= a0;
  imageStore(uOutput, pixel, vec4(filtered, pc.last != 0u ? 1.0 : samples));
}
