#include "engine/render/environment_tables.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "shaders/shared/environment.h"
#include "shaders/shared/sampling.h"

namespace qlight::render {
namespace {

// Inclusive CDF of `weights` normalised to end at exactly 1, written at cdf[at...]; uniform
// when they are all 0.
void writeCdf(const std::vector<double>& weights, std::vector<float>& cdf, size_t at) {
  double total = 0.0;
  for (double w : weights) total += w;
  double running = 0.0;
  for (size_t i = 0; i < weights.size(); ++i) {
    running += total > 0.0 ? weights[i] : 1.0;
    cdf[at + i] = float(running / (total > 0.0 ? total : double(weights.size())));
  }
  cdf[at + weights.size() - 1] = 1.0f;
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
  const uint32_t tilesX = std::min(shared::kEnvironmentTilesX, w);
  const uint32_t tilesY = std::min(shared::kEnvironmentTilesY, h);
  t.texels.reserve(shared::kEnvironmentHeaderTexels + size_t(w) * h);
  t.texels.push_back(glm::vec4(float(w), float(h), std::cos(rotation), std::sin(rotation)));
  t.texels.push_back(glm::vec4(float(tilesX), float(tilesY), 0.0f, 0.0f));
  t.cdf.resize(size_t(w) * h + size_t(tilesX) * h);
  t.tileLuminanceIntegrals.assign(size_t(tilesX) * tilesY, 0.0);

  // Each row's CDF within each tile's columns, and the weight of that row segment.
  std::vector<double> segmentWeights(size_t(tilesX) * h, 0.0);  // [tx * h + row]
  for (uint32_t row = 0; row < h; ++row) {
    const double sinTheta = shared::environmentRowCentreSin(row, h);
    // Exact solid angle of a pixel of this row, for the integrals.
    const double cos0 = std::cos(shared::kPi * double(row) / h);
    const double cos1 = std::cos(shared::kPi * double(row + 1) / h);
    const double pixelSolidAngle = 2.0 * shared::kPi / w * (cos0 - cos1);
    const uint32_t ty = shared::environmentTileAt(row, tilesY, h);
    for (uint32_t tx = 0; tx < tilesX; ++tx) {
      const uint32_t col0 = shared::environmentTileStart(tx, tilesX, w);
      const uint32_t col1 = shared::environmentTileStart(tx + 1, tilesX, w);
      std::vector<double> weights;
      for (uint32_t col = col0; col < col1; ++col) {
        const double lum = shared::luminance(env.radiance[size_t(row) * w + col]);
        weights.push_back(lum * sinTheta);
        segmentWeights[size_t(tx) * h + row] += weights.back();
        t.tileLuminanceIntegrals[size_t(ty) * tilesX + tx] += lum * pixelSolidAngle;
      }
      writeCdf(weights, t.cdf, size_t(row) * w + col0);
    }
  }
  // Each tile's CDF over its rows.
  const size_t marginal = size_t(w) * h;
  for (uint32_t tx = 0; tx < tilesX; ++tx)
    for (uint32_t ty = 0; ty < tilesY; ++ty) {
      const uint32_t row0 = shared::environmentTileStart(ty, tilesY, h);
      const uint32_t row1 = shared::environmentTileStart(ty + 1, tilesY, h);
      const auto first = segmentWeights.begin() + ptrdiff_t(size_t(tx) * h + row0);
      writeCdf(std::vector<double>(first, first + (row1 - row0)), t.cdf,
               marginal + size_t(tx) * h + row0);
    }
  for (double tile : t.tileLuminanceIntegrals) t.luminanceIntegral += tile;

  // Each pixel's density in (u, v) under its tile's sampler: the float steps it walks.
  const float pixels = float(w) * float(h);
  for (uint32_t row = 0; row < h; ++row)
    for (uint32_t col = 0; col < w; ++col) {
      const uint32_t tx = shared::environmentTileAt(col, tilesX, w);
      const uint32_t row0 =
          shared::environmentTileStart(shared::environmentTileAt(row, tilesY, h), tilesY, h);
      const uint32_t col0 = shared::environmentTileStart(tx, tilesX, w);
      const size_t rowBase = marginal + size_t(tx) * h + row0;
      const float rowProbability =
          segmentWeights[size_t(tx) * h + row] > 0.0 ? stepOf(t.cdf, rowBase, row - row0) : 0.0f;
      const float p = rowProbability * stepOf(t.cdf, size_t(row) * w + col0, col - col0) * pixels;
      t.texels.push_back(glm::vec4(env.radiance[size_t(row) * w + col], p));
    }
  return t;
}

}  // namespace qlight::render
