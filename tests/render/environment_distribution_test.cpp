// The environment map's sampler (shaders/shared/environment.h, on CPU copies of the tables
// the renderer builds): its pdf integrates to 1 over the sphere, every pixel gets the share
// luminance x sin(theta) says, samples follow the pdf (chi-square), and the pdf a sample
// states is the one a scattered ray in that direction looks up (what MIS needs).
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
  loadEnvironmentTables(env);
  EnvironmentMap e = shared::environmentMapHeader();
  ASSERT_EQ(e.width, env.width);
  ASSERT_EQ(e.height, env.height);
  // Midpoint rule per pixel in (theta, phi) of the map: pdf x sin(theta) is constant within a
  // pixel, so the rule is exact but for rounding.
  const std::vector<double> shares = expectedShares(env);
  constexpr int kSub = 4;
  double total = 0.0;
  for (uint32_t row = 0; row < env.height; ++row)
    for (uint32_t col = 0; col < env.width; ++col) {
      double pixel = 0.0;
      for (int a = 0; a < kSub; ++a)
        for (int b = 0; b < kSub; ++b) {
          glm::vec2 uv((col + (b + 0.5f) / kSub) / env.width,
                       (row + (a + 0.5f) / kSub) / env.height);
          glm::vec3 w = shared::environmentWorldFromMap(e, shared::environmentDirectionOfUv(uv));
          double theta = kPiD * uv.y;
          double cell = (2 * kPiD / (env.width * kSub)) * (kPiD / (env.height * kSub));
          pixel += shared::environmentLookup(e, w).w * std::sin(theta) * cell;
        }
      const double expected = shares[row * env.width + col];
      EXPECT_NEAR(pixel, expected, 1e-6 + 1e-4 * expected) << "pixel " << col << ", " << row;
      total += pixel;
    }
  EXPECT_NEAR(total, 1.0, 1e-5);
}

TEST(EnvironmentDistribution, SamplesFollowThePdfAndStateTheLookedUpPdf) {
  scene::EnvironmentAsset env = testMap();
  loadEnvironmentTables(env);
  EnvironmentMap e = shared::environmentMapHeader();
  const std::vector<double> shares = expectedShares(env);
  constexpr int kSamples = 400000;
  std::vector<double> observed(shares.size(), 0.0);
  TestRandom rnd(11);
  int mismatches = 0;
  for (int i = 0; i < kSamples; ++i) {
    shared::EnvironmentSample s = shared::sampleEnvironment(e, rnd.next2());
    ASSERT_NEAR(glm::length(s.direction), 1.0f, 1e-5f);
    ASSERT_GT(s.pdf, 0.0f);
    size_t pixel = pixelOf(env, s.direction);
    observed[pixel] += 1.0;
    // A scattered ray in the same direction must see the same density (within rounding of
    // the trigonometry; a direction on a pixel's very edge may land in its neighbour).
    glm::vec4 looked = shared::environmentLookup(e, s.direction);
    if (std::abs(looked.w - s.pdf) > 1e-3f * s.pdf || glm::vec3(looked) != s.radiance ||
        s.radiance != env.radiance[pixel])
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
  loadEnvironmentTables(env);
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
    observed[pixelOf(env, shared::sampleEnvironment(e, rnd.next2()).direction)] += 1.0;
  for (size_t i = 0; i < shares.size(); ++i) expected[i] = shares[i] * kSamples;
  EXPECT_FALSE(chiSquareTest(observed, expected).pass());
}

// The map's luminance integral (its power, per unit cross-section) of a uniform map is
// 4 pi L, whatever the resolution.
TEST(EnvironmentDistribution, LuminanceIntegralOfAUniformMapIsFourPiL) {
  scene::EnvironmentAsset env;
  env.width = 7;
  env.height = 5;
  env.radiance.assign(35, glm::vec3(2.0f));
  EXPECT_NEAR(render::buildEnvironmentTables(env).luminanceIntegral, 4 * kPiD * 2.0, 1e-5);
}

}  // namespace
}  // namespace qlight::test
