// Linear radiance -> display sRGB, shared by the GPU display pass and the PNG writer.
#ifndef QLIGHT_SHARED_TONEMAP_H
#define QLIGHT_SHARED_TONEMAP_H
#include "common.h"

QL_BEGIN
QL_CONST uint kTonemapClamp = 0u;
QL_CONST uint kTonemapAces = 1u;

// Narkowicz's fit of the ACES filmic curve: keeps bright emitters from clipping flat.
QL_FN vec3 tonemapAces(vec3 x) {
  vec3 num = x * (2.51f * x + 0.03f);
  vec3 den = x * (2.43f * x + 0.59f) + 0.14f;
  return clamp(num / den, vec3(0.0f), vec3(1.0f));
}

QL_FN float linearToSrgb(float c) {
  c = clamp(c, 0.0f, 1.0f);
  return c <= 0.0031308f ? 12.92f * c : 1.055f * pow(c, 1.0f / 2.4f) - 0.055f;
}

QL_FN float srgbToLinear(float c) {
  return c <= 0.04045f ? c / 12.92f : pow((c + 0.055f) / 1.055f, 2.4f);
}

// NaN or negative input shows as black rather than spreading through the curve.
QL_FN vec3 displayFromLinear(vec3 radiance, float exposure, uint op) {
  vec3 x = max(radiance * exposure, vec3(0.0f));
  if (!(x.x == x.x) || !(x.y == x.y) || !(x.z == x.z)) x = vec3(0.0f);
  vec3 mapped = op == kTonemapAces ? tonemapAces(x) : clamp(x, vec3(0.0f), vec3(1.0f));
  return vec3(linearToSrgb(mapped.x), linearToSrgb(mapped.y), linearToSrgb(mapped.z));
}
QL_END

#endif
