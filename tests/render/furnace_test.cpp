// White furnace: inside a closed box whose walls all have albedo a and emit E,
// the radiance everywhere is E / (1 - a) (the geometric series of bounces).
// Checks the estimators end to end: emission, NEE, BSDF sampling, MIS weights
// and Russian roulette must all be unbiased for the image to come out right.
#include "tests/render/furnace_scene.h"

namespace qlight::test {
namespace {

struct FurnaceCase {
  float albedo;
  float emission;
  render::Estimator estimator;
};

class Furnace : public GpuTest, public ::testing::WithParamInterface<FurnaceCase> {};

TEST_P(Furnace, RadianceIsEmissionOverOneMinusAlbedo) {
  FurnaceCase c = GetParam();
  scene::SceneAsset asset = whiteFurnace(c.albedo, c.emission);
  render::RenderSettings s = smallSettings(32, 32, 7);
  s.estimator = c.estimator;
  s.maxDepth = 1024;  // effectively unbounded: Russian roulette ends the paths
  s.russianRoulette = true;
  auto r = session::renderScene(ctx(), asset, s, 32, 0.0f);
  EXPECT_EQ(r.stats.counters.invalidSamples, 0u);

  // All pixels share the expectation, so their spread gives the standard
  // error of the image mean.
  const double expected = c.emission / (1.0 - c.albedo);
  std::vector<double> pixels;
  for (size_t i = 0; i < r.image.rgba.size(); i += 4) pixels.push_back(r.image.rgba[i + 1]);
  Moments m = moments(pixels);
  EXPECT_NEAR(m.mean, expected, 5.0 * m.standardError() + 1e-4 * expected)
      << "standard error " << m.standardError();
  // The test can tell: losing the bounces past the fourth would be far outside.
  double truncated = expected * (1.0 - std::pow(c.albedo, 5.0));
  EXPECT_GT(std::abs(truncated - expected), 5.0 * m.standardError());
}

INSTANTIATE_TEST_SUITE_P(AlbedosAndEstimators, Furnace,
                         ::testing::Values(FurnaceCase{0.5f, 1.0f, render::Estimator::Mis},
                                           FurnaceCase{0.8f, 0.5f, render::Estimator::Mis},
                                           FurnaceCase{0.8f, 0.5f, render::Estimator::BsdfOnly},
                                           FurnaceCase{0.8f, 0.5f, render::Estimator::NeeOnly}));

}  // namespace
}  // namespace qlight::test
