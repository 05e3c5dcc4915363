// Guiding changes where paths go, never what they converge to: guided and
// unguided renders agree within their noise, with NEE on and off, on the easy
// scene and on the hard one, with the strata and with direction trees. Q learns across the
// frames of each render.
#include "tests/render/agreement.h"

namespace qlight::test {
namespace {

struct UnbiasedCase {
  const char* scene;
  bool nee;
  uint32_t blocks;  // the door without NEE is too noisy per region: whole image only
  uint32_t spp;
  bool trees = false;  // direction trees per point instead of the strata
};

class GuidedUnbiased : public GpuTest, public ::testing::WithParamInterface<UnbiasedCase> {};

TEST_P(GuidedUnbiased, GuidedEqualsUnguidedWithinNoise) {
  UnbiasedCase c = GetParam();
  scene::SceneAsset asset = gltf::loadGltf(assetPath(c.scene));
  AgreementSetup setup;
  setup.size = 32;
  setup.blocks = c.blocks;
  auto with = [&](bool guided) {
    return [&, guided](uint32_t seed) {
      render::RenderSettings s = smallSettings(setup.size, setup.size, seed);
      s.estimator = c.nee ? render::Estimator::Mis : render::Estimator::BsdfOnly;
      s.maxDepth = 6;
      s.samplesPerFrame = 2;  // several frames: Q learns while the image accumulates
      guiding::GuidingSettings g;
      g.enabled = guided;
      g.pointBudget = 4096;
      g.dartPaths = 8192;
      g.seed = seed;
      if (c.trees) g.directions = guiding::DirectionModel::Tree;
      auto r = session::renderScene(ctx(), asset, s, c.spp, 0.0f, g);
      EXPECT_EQ(r.stats.counters.invalidSamples, 0u);
      if (guided) {
        EXPECT_GT(r.stats.guidingStats.points, 100u);
      }
      return r.image;
    };
  };
  auto off = regionMeans(setup, with(false), 100);
  auto on = regionMeans(setup, with(true), 200);
  expectAgree(on, off, c.scene);
}

INSTANTIATE_TEST_SUITE_P(Scenes, GuidedUnbiased,
                         ::testing::Values(UnbiasedCase{"cornell_box.gltf", true, 4, 16},
                                           UnbiasedCase{"cornell_box.gltf", false, 4, 16},
                                           UnbiasedCase{"door_ajar.gltf", true, 2, 16},
                                           UnbiasedCase{"door_ajar.gltf", false, 1, 32},
                                           UnbiasedCase{"door_ajar.gltf", true, 2, 16, true}),
                         [](const auto& info) {
                           return std::string(info.param.scene[0] == 'c' ? "Cornell" : "Door") +
                                  (info.param.nee ? "Nee" : "NoNee") +
                                  (info.param.trees ? "Trees" : "");
                         });

}  // namespace
}  // namespace qlight::test
