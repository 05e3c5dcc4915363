// Guided sampling at the highest share the settings allow (0.95) and full trust from the
// first update, by the cache points' Q tables and by the deep Q network (evaluated at each
// vertex or read from its baked grid): nearly every direction comes from the learned
// distribution, so its pdf must be exactly the density it samples, whatever was learned. The
// renders must still converge to the right answer:
//  - a white furnace (closed box, albedo a, emission E everywhere) equals
//    E / (1 - a). Scattering only, so each bounce's weight is f cos / pdf: a
//    guided pdf 5% off scales every bounce by ~1/1.05 and the image by ~15%
//    (a = 0.8), hundreds of standard errors here (shown for both methods);
//  - on the door scene guided and unguided renders agree within their noise.
#include "tests/render/agreement.h"
#include "tests/render/furnace_scene.h"

namespace qlight::test {
namespace {

// Q tables, deep Q evaluated at every vertex, deep Q read from its baked grid.
struct Guide {
  guiding::GuideMethod method;
  uint32_t dqnGrid;
};
void PrintTo(const Guide& g, std::ostream* os) {
  if (g.method == guiding::GuideMethod::Q)
    *os << "Q tables";
  else
    *os << "deep Q, grid " << g.dqnGrid;
}

guiding::GuidingSettings highShare(Guide guide, uint32_t seed) {
  guiding::GuidingSettings g;
  g.method = guide.method;
  g.dqnGrid = guide.dqnGrid;
  g.selectProbability = 0.95f;
  g.confidenceUpdates = 0.0f;  // every point guides at the full share at once
  g.pointBudget = 2048;
  g.dartPaths = 8192;
  g.dqnWarmupSteps = 0;  // and so does the network
  g.dqnBatch = 256;
  g.seed = seed;
  return g;
}

class GuidedHighShare : public GpuTest, public ::testing::WithParamInterface<Guide> {};

TEST_P(GuidedHighShare, WhiteFurnaceIsEmissionOverOneMinusAlbedo) {
  const float albedo = 0.8f, emission = 0.5f;
  scene::SceneAsset asset = whiteFurnace(albedo, emission);
  render::RenderSettings s = smallSettings(32, 32, 11);
  s.estimator = render::Estimator::BsdfOnly;
  s.maxDepth = 1024;  // Russian roulette ends the paths
  s.russianRoulette = true;
  s.samplesPerFrame = 2;  // Q (or the network) learns, noisily, between the frames
  auto r = session::renderScene(ctx(), asset, s, 64, 0.0f, highShare(GetParam(), 3));
  EXPECT_EQ(r.stats.counters.invalidSamples, 0u);
  EXPECT_TRUE(r.stats.guided);
  if (GetParam().method == guiding::GuideMethod::Q) {
    EXPECT_GT(r.stats.guidingStats.points, 100u);
    // Most vertices found a point, so most directions were guided.
    EXPECT_GT(double(r.stats.counters.coveredVertices),
              0.8 * double(r.stats.counters.pathVertices));
  }
  const double expected = emission / (1.0 - albedo);
  std::vector<double> pixels;
  for (size_t i = 0; i < r.image.rgba.size(); i += 4) pixels.push_back(r.image.rgba[i + 1]);
  Moments m = moments(pixels);
  EXPECT_NEAR(m.mean, expected, 5.0 * m.standardError() + 1e-4 * expected)
      << "standard error " << m.standardError();
  // A guided pdf 5% too large at a share of 0.95 gives E / (1 - a / (1 + 0.05 * 0.95)).
  const double wrongPdf = emission / (1.0 - albedo / (1.0 + 0.05 * 0.95));
  EXPECT_GT(std::abs(wrongPdf - expected), 20.0 * m.standardError());
}

TEST_P(GuidedHighShare, DoorAgreesWithUnguidedWithinNoise) {
  scene::SceneAsset asset = gltf::loadGltf(assetPath("door_ajar.gltf"));
  AgreementSetup setup;
  setup.size = 32;
  setup.blocks = 2;
  auto with = [&](bool guided) {
    return [&, guided](uint32_t seed) {
      render::RenderSettings s = smallSettings(setup.size, setup.size, seed);
      s.maxDepth = 6;
      s.samplesPerFrame = 2;
      guiding::GuidingSettings g = highShare(GetParam(), seed);
      g.enabled = guided;
      auto r = session::renderScene(ctx(), asset, s, 16, 0.0f, g);
      EXPECT_EQ(r.stats.counters.invalidSamples, 0u);
      return r.image;
    };
  };
  expectAgree(regionMeans(setup, with(true), 300), regionMeans(setup, with(false), 400),
              "door, guided share 0.95");
}

INSTANTIATE_TEST_SUITE_P(Methods, GuidedHighShare,
                         ::testing::Values(Guide{guiding::GuideMethod::Q, 0},
                                           Guide{guiding::GuideMethod::Dqn, 0},
                                           Guide{guiding::GuideMethod::Dqn, 8}),
                         [](const auto& info) {
                           if (info.param.method == guiding::GuideMethod::Q) return "QTables";
                           return info.param.dqnGrid == 0 ? "DeepQ" : "DeepQBakedGrid";
                         });

}  // namespace
}  // namespace qlight::test
