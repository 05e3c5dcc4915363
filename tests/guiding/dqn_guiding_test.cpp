// Guided renders with the deep Q network (--guiding dqn) converge to the right answer:
// its sampling and pdf are the tables' code on the network's outputs, unbiased whatever the
// network says. At the highest guided share (0.95) from the first frame:
//  - a white furnace equals E / (1 - a); a guided pdf 5% off would move it by ~15%,
//    tens of standard errors here;
//  - on the door scene guided and unguided renders agree within their noise.
#include "tests/render/agreement.h"
#include "tests/render/furnace_scene.h"

namespace qlight::test {
namespace {

guiding::GuidingSettings dqnAtFullShare(uint32_t seed) {
  guiding::GuidingSettings g;
  g.method = guiding::GuideMethod::Dqn;
  g.selectProbability = 0.95f;
  g.dqnWarmupSteps = 0;  // the network guides at the full share from the first frame
  g.dqnWidth = 16;
  g.dqnBatch = 256;
  g.seed = seed;
  return g;
}

class DqnGuiding : public GpuTest {};

TEST_F(DqnGuiding, WhiteFurnaceIsEmissionOverOneMinusAlbedo) {
  const float albedo = 0.8f, emission = 0.5f;
  scene::SceneAsset asset = whiteFurnace(albedo, emission);
  render::RenderSettings s = smallSettings(32, 32, 11);
  s.estimator = render::Estimator::BsdfOnly;
  s.maxDepth = 1024;  // Russian roulette ends the paths
  s.russianRoulette = true;
  s.samplesPerFrame = 2;  // the network trains between the frames
  auto r = session::renderScene(ctx(), asset, s, 64, 0.0f, dqnAtFullShare(3));
  EXPECT_EQ(r.stats.counters.invalidSamples, 0u);
  EXPECT_TRUE(r.stats.guided);
  const double expected = emission / (1.0 - albedo);
  std::vector<double> pixels;
  for (size_t i = 0; i < r.image.rgba.size(); i += 4) pixels.push_back(r.image.rgba[i + 1]);
  Moments m = moments(pixels);
  EXPECT_NEAR(m.mean, expected, 5.0 * m.standardError() + 1e-4 * expected)
      << "standard error " << m.standardError();
  const double wrongPdf = emission / (1.0 - albedo / (1.0 + 0.05 * 0.95));
  EXPECT_GT(std::abs(wrongPdf - expected), 20.0 * m.standardError());
}

TEST_F(DqnGuiding, DoorAgreesWithUnguidedWithinNoise) {
  scene::SceneAsset asset = gltf::loadGltf(assetPath("door_ajar.gltf"));
  AgreementSetup setup;
  setup.size = 32;
  setup.blocks = 2;
  auto with = [&](bool guided) {
    return [&, guided](uint32_t seed) {
      render::RenderSettings s = smallSettings(setup.size, setup.size, seed);
      s.maxDepth = 6;
      s.samplesPerFrame = 2;
      guiding::GuidingSettings g = dqnAtFullShare(seed);
      g.enabled = guided;
      auto r = session::renderScene(ctx(), asset, s, 16, 0.0f, g);
      EXPECT_EQ(r.stats.counters.invalidSamples, 0u);
      return r.image;
    };
  };
  expectAgree(regionMeans(setup, with(true), 300), regionMeans(setup, with(false), 400),
              "door, deep Q at share 0.95");
}

}  // namespace
}  // namespace qlight::test
