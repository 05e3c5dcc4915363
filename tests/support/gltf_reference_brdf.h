// The glTF 2.0 metallic-roughness reference model, written out in double
// precision from the specification's appendix B, independently of
// shaders/shared/bsdf.h: fresnel_mix of a Lambertian base and a GGX layer by
// the Schlick Fresnel of the half vector (F0 0.04), the conductor's Fresnel
// from the base colour, and height-correlated Smith visibility as the Khronos
// sample renderer evaluates it. Local frame: z is the normal.
#pragma once
#include <algorithm>
#include <cmath>

namespace qlight::test {

struct Dir {
  double x, y, z;
};

inline double gltfReferenceBrdf(double base, double metallic, double roughness, Dir wo, Dir wi) {
  const double pi = 3.14159265358979323846;
  double nv = wo.z, nl = wi.z;
  if (nv <= 0 || nl <= 0) return 0;
  double hx = wo.x + wi.x, hy = wo.y + wi.y, hz = wo.z + wi.z;
  double hl = std::sqrt(hx * hx + hy * hy + hz * hz);
  double nh = hz / hl;
  double vh = (wo.x * hx + wo.y * hy + wo.z * hz) / hl;
  double a = std::max(roughness * roughness, 1e-3);  // the renderer's alpha floor
  double a2 = a * a;
  double d = a2 / (pi * std::pow(nh * nh * (a2 - 1) + 1, 2));
  double v =
      0.5 / (nl * std::sqrt(nv * nv * (1 - a2) + a2) + nv * std::sqrt(nl * nl * (1 - a2) + a2));
  double schlick = std::pow(1 - std::abs(vh), 5);
  double fDielectric = 0.04 + 0.96 * schlick;
  double fMetal = base + (1 - base) * schlick;
  double dielectric = (1 - fDielectric) * base / pi + fDielectric * d * v;
  double metal = fMetal * d * v;
  return (1 - metallic) * dielectric + metallic * metal;
}

// Directional albedo int f cos dwi of the reference for wo at thetaO from the
// normal: a midpoint rule in (cos theta_i, phi), fine enough (n x 4n) that its
// error is below 1e-4 for roughness >= 0.3.
inline double gltfReferenceAlbedo(double base, double metallic, double roughness, double thetaO,
                                  int n = 400) {
  const double pi = 3.14159265358979323846;
  Dir wo{std::sin(thetaO), 0, std::cos(thetaO)};
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    double mu = (i + 0.5) / n;
    double s = std::sqrt(1 - mu * mu);
    for (int j = 0; j < 4 * n; ++j) {
      double phi = 2 * pi * (j + 0.5) / (4 * n);
      Dir wi{s * std::cos(phi), s * std::sin(phi), mu};
      sum += gltfReferenceBrdf(base, metallic, roughness, wo, wi) * mu;
    }
  }
  return sum * (1.0 / n) * (2 * pi / (4 * n));
}

}  // namespace qlight::test
