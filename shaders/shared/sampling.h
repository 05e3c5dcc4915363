// Sampling building blocks shared by GLSL and C++: shading frames, hemisphere
// and sphere directions, points on triangles, MIS weights. Every sampler maps
// u in [0,1)^2 and comes with the pdf of what it returns (solid angle for
// directions, area for points).
#ifndef QLIGHT_SHARED_SAMPLING_H
#define QLIGHT_SHARED_SAMPLING_H

#include "common.h"

QL_BEGIN

// Orthonormal, right-handed: cross(tangent, bitangent) == normal.
struct TangentFrame {
  vec3 tangent;
  vec3 bitangent;
  vec3 normal;
};

// Duff et al. 2017, "Building an Orthonormal Basis, Revisited": no branch on
// the normal's direction except a sign select, continuous except at z = 0.
QL_FN TangentFrame frameFromNormal(vec3 n) {
  float s = n.z >= 0.0f ? 1.0f : -1.0f;
  float a = -1.0f / (s + n.z);
  float b = n.x * n.y * a;
  TangentFrame f;
  f.tangent = vec3(1.0f + s * n.x * n.x * a, s * b, -s * n.x);
  f.bitangent = vec3(b, s + n.y * n.y * a, -n.y);
  f.normal = n;
  return f;
}

QL_FN vec3 localFromWorld(TangentFrame f, vec3 v) {
  return vec3(dot(v, f.tangent), dot(v, f.bitangent), dot(v, f.normal));
}

QL_FN vec3 worldFromLocal(TangentFrame f, vec3 v) {
  return v.x * f.tangent + v.y * f.bitangent + v.z * f.normal;
}

// Shirley & Chiu concentric map from the square to the unit disk.
QL_FN vec2 sampleConcentricDisk(vec2 u) {
  vec2 p = 2.0f * u - vec2(1.0f);
  if (p.x == 0.0f && p.y == 0.0f) return vec2(0.0f);
  float r;
  float theta;
  if (abs(p.x) > abs(p.y)) {
    r = p.x;
    theta = 0.25f * kPi * (p.y / p.x);
  } else {
    r = p.y;
    theta = 0.5f * kPi - 0.25f * kPi * (p.x / p.y);
  }
  return r * vec2(cos(theta), sin(theta));
}

// Cosine-weighted hemisphere around +z (Malley: lift the concentric disk).
QL_FN vec3 sampleCosineHemisphere(vec2 u) {
  vec2 d = sampleConcentricDisk(u);
  float z = sqrt(max(0.0f, 1.0f - d.x * d.x - d.y * d.y));
  return vec3(d.x, d.y, z);
}

QL_FN float cosineHemispherePdf(float cosTheta) { return max(cosTheta, 0.0f) * kInvPi; }

QL_FN vec3 sampleUniformHemisphere(vec2 u) {
  float z = u.x;
  float r = sqrt(max(0.0f, 1.0f - z * z));
  float phi = kTwoPi * u.y;
  return vec3(r * cos(phi), r * sin(phi), z);
}

QL_FN float uniformHemispherePdf() { return 0.5f * kInvPi; }

QL_FN vec3 sampleUniformSphere(vec2 u) {
  float z = 1.0f - 2.0f * u.x;
  float r = sqrt(max(0.0f, 1.0f - z * z));
  float phi = kTwoPi * u.y;
  return vec3(r * cos(phi), r * sin(phi), z);
}

QL_FN float uniformSpherePdf() { return 0.25f * kInvPi; }

// Barycentrics (b0, b1, b2) uniform on a triangle: Heitz 2019, "A Low-Distortion
// Map Between Triangle and Square" (no square root, neighbouring u stay close).
QL_FN vec3 sampleTriangleBarycentrics(vec2 u) {
  float b0;
  float b1;
  if (u.x < u.y) {
    b0 = 0.5f * u.x;
    b1 = u.y - b0;
  } else {
    b1 = 0.5f * u.y;
    b0 = u.x - b1;
  }
  return vec3(b0, b1, 1.0f - b0 - b1);
}

QL_FN vec3 sampleTrianglePoint(vec3 p0, vec3 p1, vec3 p2, vec2 u) {
  vec3 b = sampleTriangleBarycentrics(u);
  return b.x * p0 + b.y * p1 + b.z * p2;
}

QL_FN float triangleArea(vec3 p0, vec3 p1, vec3 p2) {
  return 0.5f * length(cross(p1 - p0, p2 - p0));
}

// Converts an area pdf at a light point to a solid-angle pdf seen from the
// shading point. Returns 0 when the light is seen edge-on (no direction).
QL_FN float solidAnglePdfFromArea(float areaPdf, float distanceSquared, float cosAtLight) {
  float c = abs(cosAtLight);
  return c > 0.0f ? areaPdf * distanceSquared / c : 0.0f;
}

// Veach's power heuristic (beta = 2) for nf samples of pdf fPdf against ng of
// gPdf. Works on the ratio so huge pdfs do not overflow when squared; an
// infinite fPdf (delta) gives 1, a zero or NaN fPdf gives 0.
QL_FN float powerHeuristic(float nf, float fPdf, float ng, float gPdf) {
  float f = nf * fPdf;
  float g = ng * gPdf;
  if (!(f > 0.0f)) return 0.0f;
  if (!(g > 0.0f)) return 1.0f;
  if (f == g) return 0.5f;
  if (f > g) {
    float r = g / f;
    return 1.0f / (1.0f + r * r);
  }
  float r = f / g;
  float r2 = r * r;
  return r2 / (1.0f + r2);
}

// Rec. 709 / sRGB primaries, linear.
QL_FN float luminance(vec3 c) { return dot(c, vec3(0.2126f, 0.7152f, 0.0722f)); }

QL_END

#endif
