// The environment map's sampler (shaders/shared/environment.h, on CPU copies of the tables
// the renderer builds): a tile chosen by its power, then a direction within it. Each tile's
// pdf integrates to 1 over the tile, every pixel gets the share luminance x sin(theta) says,
// samples follow the pdf (chi-square), and the pdf and tile a sample states are the ones a
// scattered ray in that direction looks up (what MIS needs).
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/constants.hpp>

#include "tests/math/sphere_quadrature.h"
#include "tests/math/stats_support.h"
#include "tests/render/environment_harness.h"

namespace qlight::test {
namespace {

using shared::EnvironmentMap;

// 24 x 12 texels with a range of values, a sun 100x brighter than the sky, a black row
// and black pixels, turned by 37 degrees.
scene::EnvironmentAsset testMap() {
  scene::EnvironmentAsset env;
  env.width = 24;
  env.height = 12;
  env.rotationDegrees = 37.0f;
  for (uint32_t row = 0; row < env.height; ++row)
    for (uint32_t col = 0; col < env.width; ++col) {
      float base = 0.2f + 0.8f * float((col * 7 + row * 3) % 11) / 10.0f;
      glm::vec3 l(base, 0.5f * base, 0.1f + 0.05f * float(row));
      if (row == 9 || (col + row) % 13 == 0) l = glm::vec3(0.0f);
      if (row == 3 && col == 5) l = glm::vec3(100.0f, 90.0f, 80.0f);
      env.radiance.push_back(l);
    }
  return env;
}

// The share of samples each pixel should get, from the radiance alone (not the tables).
std::vector<double> expectedShares(const scene::EnvironmentAsset& env) {
  std::vector<double> w(env.radiance.size());
  double total = 0.0;
  for (uint32_t row = 0; row < env.height; ++row)
    for (uint32_t col = 0; col < env.width; ++col) {
      glm::vec3 l = env.radiance[row * env.width + col];
      double lum = 0.2126 * l.x + 0.7152 * l.y + 0.0722 * l.z;
      double s = std::sin(kPiD * (row + 0.5) / env.height);
      total += w[row * env.width + col] = lum * s;
    }
  for (double& x : w) x /= total;
  return w;
}

// Tile t's probability of being chosen by power: its share of the map's luminance integral.
std::vector<double> tileShares(const render::EnvironmentTables& t) {
  std::vector<double> shares;
  for (double tile : t.tileLuminanceIntegrals) shares.push_back(tile / t.luminanceIntegral);
  return shares;
}

struct MapSample {
  shared::EnvironmentSample s;
  uint32_t tile;
};

// The renderer's light selection by power restricted to the sky: a tile by its share, then
// a direction within the tile.
MapSample sampleMap(EnvironmentMap e, const std::vector<double>& tiles, TestRandom& rnd) {
  double u = rnd.next(), running = 0.0;
  uint32_t tile = 0;
  while (tile + 1 < tiles.size() && (running += tiles[tile]) <= u) ++tile;
  return {shared::sampleEnvironmentTile(e, tile, rnd.next2()), tile};
}

// The pixel a world direction falls in, by the test's own trigonometry.
size_t pixelOf(const scene::EnvironmentAsset& env, glm::vec3 world) {
  double r = glm::radians(double(env.rotationDegrees));
  // Map from world: rotate by -r about +Y.
  double x = world.x * std::cos(r) - world.z * std::sin(r);
  double z = world.x * std::sin(r) + world.z * std::cos(r);
  double theta = std::atan2(std::hypot(x, z), double(world.y));
  double phi = std::atan2(x, -z);
  int col = std::clamp(int((0.5 + phi / (2 * kPiD)) * env.width), 0, int(env.width) - 1);
  int row = std::clamp(int(theta / kPiD * env.height), 0, int(env.height) - 1);
  return size_t(row) * env.width + col;
}

TEST(EnvironmentDistribution, PdfIntegratesToOneAndEachPixelHoldsItsShare) {
  scene::EnvironmentAsset env = testMap();
  const render::EnvironmentTables tables = loadEnvironmentTables(env);
  EnvironmentMap e = shared::environmentMapHeader();
  ASSERT_EQ(e.width, env.width);
  ASSERT_EQ(e.height, env.height);
  ASSERT_EQ(e.tilesX, shared::kEnvironmentTilesX);
  ASSERT_EQ(e.tilesY, shared::kEnvironmentTilesY);
  const std::vector<double> tiles = tileShares(tables);
  // Midpoint rule per pixel in (theta, phi) of the map: pdf x sin(theta) is constant within a
  // pixel, so the rule is exact but for rounding.
  const std::vector<double> shares = expectedShares(env);
  std::vector<double> withinTile(tiles.size(), 0.0);
  constexpr int kSub = 4;
  double total = 0.0;
  for (uint32_t row = 0; row < env.height; ++row)
    for (uint32_t col = 0; col < env.width; ++col) {
      double pixel = 0.0;
      uint32_t tile = 0;
      for (int a = 0; a < kSub; ++a)
        for (int b = 0; b < kSub; ++b) {
          glm::vec2 uv((col + (b + 0.5f) / kSub) / env.width,
                       (row + (a + 0.5f) / kSub) / env.height);
          glm::vec3 w = shared::environmentWorldFromMap(e, shared::environmentDirectionOfUv(uv));
          double theta = kPiD * uv.y;
          double cell = (2 * kPiD / (env.width * kSub)) * (kPiD / (env.height * kSub));
          shared::EnvironmentTexel t = shared::environmentLookup(e, w);
          pixel += t.pdf * std::sin(theta) * cell;
          tile = t.tile;
        }
      ASSERT_EQ(tile, (row / 3) * e.tilesX + col / 3) << "3 x 3 pixels a tile";
      withinTile[tile] += pixel;
      const double expected = shares[row * env.width + col];
      EXPECT_NEAR(tiles[tile] * pixel, expected, 1e-6 + 1e-4 * expected)
          << "pixel " << col << ", " << row;
      total += tiles[tile] * pixel;
    }
  EXPECT_NEAR(total, 1.0, 1e-5);
  for (size_t t = 0; t < tiles.size(); ++t)
    if (tiles[t] > 0.0) EXPECT_NEAR(withinTile[t], 1.0, 1e-5) << "tile " << t;
}

TEST(EnvironmentDistribution, SamplesFollowThePdfAndStateTheLookedUpPdf) {
  scene::EnvironmentAsset env = testMap();
  const std::vector<double> tiles = tileShares(loadEnvironmentTables(env));
  EnvironmentMap e = shared::environmentMapHeader();
  const std::vector<double> shares = expectedShares(env);
  constexpr int kSamples = 400000;
  std::vector<double> observed(shares.size(), 0.0);
  TestRandom rnd(11);
  int mismatches = 0;
  for (int i = 0; i < kSamples; ++i) {
    MapSample m = sampleMap(e, tiles, rnd);
    ASSERT_NEAR(glm::length(m.s.direction), 1.0f, 1e-5f);
    ASSERT_GT(m.s.pdf, 0.0f);
    size_t pixel = pixelOf(env, m.s.direction);
    observed[pixel] += 1.0;
    // A scattered ray in the same direction must see the same density and tile (within
    // rounding of the trigonometry; a direction on a pixel's very edge may land in its
    // neighbour).
    shared::EnvironmentTexel looked = shared::environmentLookup(e, m.s.direction);
    if (std::abs(looked.pdf - m.s.pdf) > 1e-3f * m.s.pdf || looked.radiance != m.s.radiance ||
        looked.tile != m.tile || m.s.radiance != env.radiance[pixel])
      ++mismatches;
  }
  EXPECT_LE(mismatches, kSamples / 10000) << "samples whose lookup or pixel differs";
  std::vector<double> expected(shares.size());
  for (size_t i = 0; i < shares.size(); ++i) expected[i] = shares[i] * kSamples;
  ChiSquareResult result = chiSquareTest(observed, expected);
  EXPECT_TRUE(result.pass()) << result.describe();
}

// The test can tell a sampler that is off by a little: the same samples fail against shares
// 5% higher in the sky above 45 degrees (renormalised).
TEST(EnvironmentDistribution, ChiSquareCatchesASkyFivePercentOff) {
  scene::EnvironmentAsset env = testMap();
  const std::vector<double> tiles = tileShares(loadEnvironmentTables(env));
  EnvironmentMap e = shared::environmentMapHeader();
  std::vector<double> shares = expectedShares(env);
  for (size_t i = 0; i < 6 * env.width; ++i)
    if (i != 3 * env.width + 5) shares[i] *= 1.05;  // all but the sun
  double sum = 0.0;
  for (double s : shares) sum += s;
  for (double& s : shares) s /= sum;
  constexpr int kSamples = 400000;
  std::vector<double> observed(shares.size(), 0.0), expected(shares.size());
  TestRandom rnd(11);
  for (int i = 0; i < kSamples; ++i)
    observed[pixelOf(env, sampleMap(e, tiles, rnd).s.direction)] += 1.0;
  for (size_t i = 0; i < shares.size(); ++i) expected[i] = shares[i] * kSamples;
  EXPECT_FALSE(chiSquareTest(observed, expected).pass());
}

// Tiles partition any map: every column (row) lies in the tile whose range holds it, and
// no tile is empty while there are at least as many pixels as tiles.
TEST(EnvironmentDistribution, TilesPartitionTheMapAtAnySize) {
  for (uint32_t size = 1; size <= 40; ++size)
    for (uint32_t tiles = 1; tiles <= std::min(size, 8u); ++tiles) {
      EXPECT_EQ(shared::environmentTileStart(0, tiles, size), 0u);
      EXPECT_EQ(shared::environmentTileStart(tiles, tiles, size), size);
      for (uint32_t t = 0; t < tiles; ++t)
        EXPECT_LT(shared::environmentTileStart(t, tiles, size),
                  shared::environmentTileStart(t + 1, tiles, size));
      for (uint32_t i = 0; i < size; ++i) {
        const uint32_t t = shared::environmentTileAt(i, tiles, size);
        ASSERT_LT(t, tiles);
        EXPECT_LE(shared::environmentTileStart(t, tiles, size), i);
        EXPECT_GT(shared::environmentTileStart(t + 1, tiles, size), i) << size << " " << tiles;
      }
    }
}

// The map's luminance integral (its power, per unit cross-section) of a uniform map is
// 4 pi L, whatever the resolution, and each tile holds its solid angle's part.
TEST(EnvironmentDistribution, LuminanceIntegralOfAUniformMapIsFourPiL) {
  scene::EnvironmentAsset env;
  env.width = 7;
  env.height = 5;
  env.radiance.assign(35, glm::vec3(2.0f));
  const render::EnvironmentTables t = render::buildEnvironmentTables(env);
  EXPECT_NEAR(t.luminanceIntegral, 4 * kPiD * 2.0, 1e-5);
  ASSERT_EQ(t.tileLuminanceIntegrals.size(), 7u * 4u);  // 8 tiles across are clamped to 7
  // A tile of rows [r0, r1) and 1 of 7 columns holds its band's solid angle, 2 pi / 7 dcos.
  for (uint32_t ty = 0; ty < 4; ++ty) {
    const double r0 = shared::environmentTileStart(ty, 4, 5);
    const double r1 = shared::environmentTileStart(ty + 1, 4, 5);
    const double band = 2 * kPiD / 7 * (std::cos(kPiD * r0 / 5) - std::cos(kPiD * r1 / 5));
    EXPECT_NEAR(t.tileLuminanceIntegrals[ty * 7 + 3], 2.0 * band, 1e-5) << "tile row " << ty;
  }
}

}  // namespace
}  // namespace qlight::test
