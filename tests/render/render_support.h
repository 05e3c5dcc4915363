// Helpers for renderer tests: small renders of shipped or procedural scenes,
// and the statistics used to compare estimators within their noise.
#pragma once
#include <cmath>
#include <vector>

#include "engine/gltf/gltf_loader.h"
#include "engine/session/offline_render.h"
#include "tests/gpu/gpu_fixture.h"

namespace qlight::test {

inline std::string assetPath(const char* name) {
  return std::string(QLIGHT_SOURCE_DIR) + "/assets/" + name;
}

inline render::RenderSettings smallSettings(uint32_t w, uint32_t h, uint32_t seed = 1) {
  render::RenderSettings s;
  s.width = w;
  s.height = h;
  s.seed = seed;
  s.samplesPerFrame = 8;
  return s;
}

// Mean and sample variance of a quantity measured on K independent renders.
struct Moments {
  double mean = 0, variance = 0;
  size_t n = 0;
  double standardError() const { return std::sqrt(variance / double(n)); }
};

inline Moments moments(const std::vector<double>& xs) {
  Moments m;
  m.n = xs.size();
  for (double x : xs) m.mean += x;
  m.mean /= double(m.n);
  for (double x : xs) m.variance += (x - m.mean) * (x - m.mean);
  m.variance /= double(m.n - 1);
  return m;
}

// Mean of channel c over a rectangle of a linear image.
inline double regionMean(const image::LinearImage& img, uint32_t x0, uint32_t y0, uint32_t x1,
                         uint32_t y1, int c) {
  double sum = 0;
  for (uint32_t y = y0; y < y1; ++y)
    for (uint32_t x = x0; x < x1; ++x) sum += img.rgba[(size_t(y) * img.width + x) * 4 + c];
  return sum / double((x1 - x0) * (y1 - y0));
}

}  // namespace qlight::test
