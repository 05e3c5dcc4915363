// Deterministic integration and binning of functions on the sphere for the
// sampling tests. Directions are parametrised by (theta, phi) around +z, each
// through a sinh-stretched axis that crowds points around a lobe centre at a
// chosen width, so narrow GGX lobes (roughness 0.05) are resolved by a modest
// grid. The midpoint rule in the stretched coordinates is second-order for
// smooth integrands, so comparing n and 2n points estimates the error
// (Richardson): |I_2n - I| ~ |I_n - I_2n| / 3.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <numbers>
#include <vector>

namespace qlight::test {

inline constexpr double kPiD = std::numbers::pi;

// x(t) = center + width sinh(lambda (t - tc)) maps [0, 1] onto [lo, hi].
struct StretchedAxis {
  double lo = 0.0, hi = 1.0, center = 0.5, width = 1.0, tc = 0.5, lambda = 1.0;

  static StretchedAxis make(double lo, double hi, double center, double width) {
    StretchedAxis a;
    a.lo = lo;
    a.hi = hi;
    a.center = std::clamp(center, lo, hi);
    a.width = width;
    double below = std::asinh((a.center - lo) / width);
    double above = std::asinh((hi - a.center) / width);
    a.lambda = below + above;
    a.tc = below / a.lambda;
    return a;
  }
  double x(double t) const { return center + width * std::sinh(lambda * (t - tc)); }
  double dxdt(double t) const { return width * lambda * std::cosh(lambda * (t - tc)); }
  double t(double x) const { return tc + std::asinh((x - center) / width) / lambda; }
};

// (theta, phi) grid: theta in [thetaLo, thetaHi], phi in [phiCenter - pi, phiCenter + pi).
struct SphereGrid {
  StretchedAxis theta;
  StretchedAxis phi;

  // Lobe around direction (thetaC, phiC) with angular width `width`.
  static SphereGrid around(double thetaLo, double thetaHi, double thetaC, double phiC,
                           double width) {
    SphereGrid g;
    g.theta = StretchedAxis::make(thetaLo, thetaHi, thetaC, width);
    double phiWidth = std::min(4.0, width / std::max(std::sin(thetaC), 1e-9));
    g.phi = StretchedAxis::make(phiC - kPiD, phiC + kPiD, phiC, phiWidth);
    return g;
  }
  static SphereGrid uniform(double thetaLo, double thetaHi) {
    return around(thetaLo, thetaHi, 0.5 * (thetaLo + thetaHi), kPiD, 1e3);
  }

  static glm::vec3 direction(double theta, double phi) {
    return glm::vec3(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)),
                     float(std::cos(theta)));
  }
  // Solid angle per unit (t_theta, t_phi) at a grid point, with its direction.
  void point(double tTheta, double tPhi, glm::vec3& w, double& jacobian) const {
    double th = theta.x(tTheta);
    double ph = phi.x(tPhi);
    w = direction(th, ph);
    jacobian = std::sin(th) * theta.dxdt(tTheta) * phi.dxdt(tPhi);
  }

  // Midpoint rule with n x n points over the whole (t_theta, t_phi) square.
  template <class F>
  double integrate(F&& f, int n) const {
    std::vector<double> cosPhi(n), sinPhi(n), dPhi(n);
    for (int j = 0; j < n; ++j) {
      double t = (j + 0.5) / n;
      cosPhi[j] = std::cos(phi.x(t));
      sinPhi[j] = std::sin(phi.x(t));
      dPhi[j] = phi.dxdt(t);
    }
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
      double t = (i + 0.5) / n;
      double th = theta.x(t);
      double s = std::sin(th), c = std::cos(th);
      double rowSum = 0.0;
      for (int j = 0; j < n; ++j) {
        glm::vec3 w(float(s * cosPhi[j]), float(s * sinPhi[j]), float(c));
        rowSum += double(f(w)) * dPhi[j];
      }
      sum += rowSum * s * theta.dxdt(t);
    }
    return sum / (double(n) * double(n));
  }

  // Bin of a direction in an nb x nb grid over (t_theta, t_phi); -1 if the
  // direction lies outside the theta range.
  int bin(glm::vec3 w, int nb) const {
    // atan2 keeps theta accurate near the poles, where float z has few digits.
    double th = std::atan2(std::hypot(double(w.x), double(w.y)), double(w.z));
    if (th < theta.lo || th > theta.hi) return -1;
    double ph = std::atan2(double(w.y), double(w.x));
    while (ph < phi.lo) ph += 2.0 * kPiD;
    while (ph >= phi.hi) ph -= 2.0 * kPiD;
    int i = std::clamp(int(theta.t(th) * nb), 0, nb - 1);
    int j = std::clamp(int(phi.t(ph) * nb), 0, nb - 1);
    return i * nb + j;
  }

  // Integral of f over each bin (sub x sub midpoints per bin).
  template <class F>
  std::vector<double> binIntegrals(F&& f, int nb, int sub) const {
    std::vector<double> out(size_t(nb) * nb, 0.0);
    int n = nb * sub;
    for (int i = 0; i < n; ++i) {
      double tt = (i + 0.5) / n;
      for (int j = 0; j < n; ++j) {
        glm::vec3 w;
        double jac;
        point(tt, (j + 0.5) / n, w, jac);
        out[size_t(i / sub) * nb + size_t(j / sub)] += double(f(w)) * jac;
      }
    }
    for (double& v : out) v /= double(n) * double(n);
    return out;
  }
};

// An integral at n and 2n points with its Richardson error estimate.
struct QuadratureResult {
  double value = 0.0;
  double errorEstimate = 0.0;
};

template <class F>
QuadratureResult integrateWithError(const SphereGrid& grid, F&& f, int n) {
  double coarse = grid.integrate(f, n);
  double fine = grid.integrate(f, 2 * n);
  return {fine, std::abs(fine - coarse) / 3.0};
}

// Integrates over theta pieces [breaks[i], breaks[i+1]] with one grid each,
// crowded around (thetaC, phiC) (clamped into the piece). Splitting at a
// theta where the integrand jumps keeps the midpoint rule second-order.
template <class F>
QuadratureResult integrateOverThetaPieces(const std::vector<double>& breaks, double thetaC,
                                          double phiC, double width, F&& f, int n) {
  QuadratureResult total;
  for (size_t i = 0; i + 1 < breaks.size(); ++i) {
    if (breaks[i + 1] - breaks[i] < 1e-12) continue;
    SphereGrid grid = SphereGrid::around(breaks[i], breaks[i + 1], thetaC, phiC, width);
    QuadratureResult r = integrateWithError(grid, f, n);
    total.value += r.value;
    total.errorEstimate += r.errorEstimate;
  }
  return total;
}

}  // namespace qlight::test
