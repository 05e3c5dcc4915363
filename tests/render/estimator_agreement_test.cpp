// BSDF sampling alone, NEE alone and their MIS combination are three unbiased
// estimators of the same image: they must agree within their noise. A wrong
// pdf or MIS weight shows up as a difference far outside it.
#include "tests/render/agreement.h"

namespace qlight::test {
namespace {

class EstimatorAgreement : public GpuTest {};

TEST_F(EstimatorAgreement, CornellBoxBsdfNeeAndMisConverge) {
  scene::SceneAsset asset = gltf::loadGltf(assetPath("cornell_box.gltf"));
  AgreementSetup setup;
  auto with = [&](render::Estimator estimator) {
    return [&, estimator](uint32_t seed) {
      render::RenderSettings s = smallSettings(setup.size, setup.size, seed);
      s.estimator = estimator;
      s.maxDepth = 4;
      auto r = session::renderScene(ctx(), asset, s, 16, 0.0f);
      EXPECT_EQ(r.stats.counters.invalidSamples, 0u);
      return r.image;
    };
  };
  auto mis = regionMeans(setup, with(render::Estimator::Mis), 1000);
  auto bsdf = regionMeans(setup, with(render::Estimator::BsdfOnly), 2000);
  auto nee = regionMeans(setup, with(render::Estimator::NeeOnly), 3000);
  expectAgree(mis, bsdf, "mis vs bsdf");
  expectAgree(mis, nee, "mis vs nee");
  expectAgree(bsdf, nee, "bsdf vs nee");

  // The comparison has power: the whole-image standard error of MIS is small
  // enough that a 5% bias in any estimator would exceed the bound.
  Moments m = imageMeans(mis);
  EXPECT_LT(kMaxWelchT * m.standardError() * std::sqrt(2.0), 0.05 * m.mean);
}

}  // namespace
}  // namespace qlight::test
