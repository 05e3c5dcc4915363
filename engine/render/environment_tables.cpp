#include "engine/render/environment_tables.h"

#include <cmath>
#include <stdexcept>

#include "shaders/shared/environment.h"
#include "shaders/shared/sampling.h"

namespace qlight::render {
namespace {

// Inclusive CDF of `weights` normalised to end at exactly 1; uniform when they are all 0.
void appendCdf(const std::vector<double>& weights, std::vector<float>& cdf) {
  double total = 0.0;
  for (double w : weights) total += w;
  double running = 0.0;
  for (size_t i = 0; i < weights.size(); ++i) {
    running += total > 0.0 ? weights[i] : 1.0;
    cdf.push_back(float(running / (total > 0.0 ? total : double(weights.size()))));
  }
  cdf.back() = 1.0f;
}

// The probability the sampler gives entry i: the float step it walks (environmentSearchCdf).
float stepOf(const std::vector<float>& cdf, size_t base, size_t i) {
  return cdf[base + i] - (i > 0 ? cdf[base + i - 1] : 0.0f);
}

}  // namespace

EnvironmentTables buildEnvironmentTables(const scene::EnvironmentAsset& env) {
  const uint32_t w = env.width, h = env.height;
  if (!env.hasMap() || env.radiance.size() != size_t(w) * h)
    throw std::invalid_argument("environment tables need a map whose size matches its texels");
  EnvironmentTables t;
  const float rotation = glm::radians(env.rotationDegrees);
  t.texels.reserve(shared::kEnvironmentHeaderTexels + size_t(w) * h);
  t.texels.push_back(glm::vec4(float(w), float(h), std::cos(rotation), std::sin(rotation)));
  t.cdf.reserve(size_t(w) * h + h);

  std::vector<double> rowWeights(h, 0.0), weights(w);
  for (uint32_t row = 0; row < h; ++row) {
    const double sinTheta = shared::environmentRowCentreSin(row, h);
    // Exact solid angle of a pixel of this row, for the integral.
    const double cos0 = std::cos(shared::kPi * double(row) / h);
    const double cos1 = std::cos(shared::kPi * double(row + 1) / h);
    const double pixelSolidAngle = 2.0 * shared::kPi / w * (cos0 - cos1);
    for (uint32_t col = 0; col < w; ++col) {
      const double lum = shared::luminance(env.radiance[size_t(row) * w + col]);
      weights[col] = lum * sinTheta;
      rowWeights[row] += weights[col];
      t.luminanceIntegral += lum * pixelSolidAngle;
    }
    appendCdf(weights, t.cdf);
  }
  const size_t marginal = size_t(w) * h;
  appendCdf(rowWeights, t.cdf);

  const float pixels = float(w) * float(h);
  for (uint32_t row = 0; row < h; ++row) {
    const float rowProbability = rowWeights[row] > 0.0 ? stepOf(t.cdf, marginal, row) : 0.0f;
    for (uint32_t col = 0; col < w; ++col) {
      const glm::vec3 l = env.radiance[size_t(row) * w + col];
      const float p = rowProbability * stepOf(t.cdf, size_t(row) * w, col) * pixels;
      t.texels.push_back(glm::vec4(l, p));
    }
  }
  return t;
}

}  // namespace qlight::render
