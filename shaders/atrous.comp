#version 460
// One iteration of the edge-aware a-trous wavelet filter (Dammertz et al. 2010) on the
// displayed image: a 5x5 B3-spline kernel with holes of `step` pixels, each tap weighted by
// how alike its primary hit is (normal, distance, base colour) and its brightness, against
// the brightness's noise (Schied et al. 2017, SVGF). The first iteration divides by the base
// colour and the last multiplies it back, so texture and material edges stay sharp. Input:
// rgb sum, a weight; the last output too (a = 1), the ones between carry the colour and its
// luminance variance. Display only.
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

// How alike two primary hits are: normals (n^64), base colours and distances (2% per step of
// the holes weighs 1/e; depthScale holds that for the centre). The exponent is returned apart
// so the caller adds its own terms to it (lavapipe evaluates exp as a polynomial on every
// lane: one per tap). 0 where a surface meets the background.
float surfaceWeight(vec4 g0, vec3 a0, vec4 g, vec3 a, float depthScale, out float exponent) {
  exponent = -length(a0 - a) * 10.0;
  if (g0.w > 0.0 && g.w > 0.0) {
    float n = max(dot(g0.xyz, g.xyz), 0.0);  // n^64 by squaring
    n *= n;
    n *= n;
    n *= n;
    n *= n;
    n *= n;
    n *= n;
    exponent -= abs(g0.w - g.w) * depthScale;
    return n;
  }
  return (g0.w > 0.0) == (g.w > 0.0) ? 1.0 : 0.0;
}

// The first pass's estimate of the centre's luminance variance: the spread of the brightness
// over its 5x5 neighbourhood, emitters left out (Schied et al. 2017's spatial estimate where
// a pixel has too few samples of its own), and at least what shot noise gives a mean of
// `samples` samples of the neighbourhood's brightness (relative deviation 1 / sqrt(samples)):
// at one sample a dim wall's neighbourhood is often all black, and a variance of 0 would keep
// its black pixels apart. `mean` gets the neighbourhood's mean brightness. The later passes
// carry each pixel's variance in alpha.
float neighbourhoodVariance(ivec2 pixel, ivec2 size, float samples, out float mean) {
  float sum = 0.0, sumSquares = 0.0, count = 0.0;  // the centre counts: never 0
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -2; dx <= 2; ++dx) {
      ivec2 q = pixel + ivec2(dx, dy);
      if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
      if (imageLoad(uAlbedo, q).a == 0.0) continue;
      float l = luminance(colourAt(q));
      sum += l;
      sumSquares += l * l;
      count += 1.0;
    }
  mean = sum / count;
  return max(sumSquares / count - mean * mean, mean * mean / max(samples, 1e-3));
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
    imageStore(uOutput, pixel, vec4(pc.last != 0u ? c0 * a0 : c0, pc.last != 0u ? 1.0 : 0.0));
    return;
  }
  // Depths differing by 2% per step of the holes weigh 1/e (the centre's, for every tap).
  float depthScale = 1.0 / (0.02 * g0.w * float(pc.step) + 1e-4);
  // Brightness edges stop the filter where they stand out of the centre's noise: a
  // luminance difference of colourSigma x 4 standard deviations weighs 1/e (SVGF's
  // sigma_l = 4). At a few samples a pixel's brightness is mostly noise, and the tolerance is
  // wide; as the accumulation converges it narrows to the image's own edges. The taps are
  // compared with the centre's brightness, in the first pass with its neighbourhood's mean:
  // a single bright or black sample is no edge.
  float l0 = luminance(c0);
  float variance = pc.first != 0u
                       ? neighbourhoodVariance(pixel, size, imageLoad(uInput, pixel).a, l0)
                       : imageLoad(uInput, pixel).a;
  float tolerance = 1.0 / (4.0 * pc.colourSigma * sqrt(variance) + 1e-4);
  vec3 sum = vec3(0.0);
  float weights = 0.0;
  float weightedVariance = 0.0;  // sum w^2 var: the output's variance times weights^2
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -2; dx <= 2; ++dx) {
      ivec2 q = pixel + pc.step * ivec2(dx, dy);
      if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
      vec4 albedo = imageLoad(uAlbedo, q);
      if (albedo.a == 0.0) continue;  // emitters stay out of their neighbours
      vec3 c = colourAt(q);
      float exponent;
      float w = kernel[abs(dx)] * kernel[abs(dy)] *
                surfaceWeight(g0, a0, imageLoad(uGbuffer, q), albedo.rgb, depthScale, exponent);
      w *= exp(exponent - abs(l0 - luminance(c)) * tolerance);
      sum += w * c;
      weights += w;
      // The first pass knows the centre's variance only: its neighbours' is taken as the same.
      weightedVariance += w * w * (pc.first != 0u ? variance : imageLoad(uInput, q).a);
    }
  vec3 filtered = weights > 0.0 ? sum / weights : c0;
  float filteredVariance = weights > 0.0 ? weightedVariance / (weights * weights) : variance;
  if (pc.last != 0u) filtered *= a0;
  imageStore(uOutput, pixel, vec4(filtered, pc.last != 0u ? 1.0 : filteredVariance));
}
