// BSDF sampling alone, NEE alone and their MIS combination are three unbiased
// estimators of the same image: they must agree within their noise. A wrong
// pdf or MIS weight shows up as a difference far outside it.
#include <array>

#include "tests/render/render_support.h"

namespace qlight::test {
namespace {

class EstimatorAgreement : public GpuTest {};

constexpr uint32_t kSize = 40;
constexpr uint32_t kBlocks = 4;  // kBlocks x kBlocks regions compared separately
constexpr uint32_t kBatches = 16;
constexpr uint32_t kSppPerBatch = 16;

// Per region and channel: the region's mean radiance in each of kBatches
// independent renders (seeds differ between batches and between estimators).
using RegionSamples = std::vector<std::vector<double>>;  // [region*3 + c][batch]

RegionSamples renderBatches(gpu::Context& ctx, const scene::SceneAsset& asset,
                            render::Estimator estimator, uint32_t seedBase) {
  RegionSamples out(kBlocks * kBlocks * 3);
  for (uint32_t b = 0; b < kBatches; ++b) {
    render::RenderSettings s = smallSettings(kSize, kSize, seedBase + b);
    s.estimator = estimator;
    s.maxDepth = 4;
    auto r = render::renderScene(ctx, asset, s, kSppPerBatch, 0.0f);
    EXPECT_EQ(r.stats.counters.invalidSamples, 0u);
    uint32_t step = kSize / kBlocks;
    for (uint32_t by = 0; by < kBlocks; ++by)
      for (uint32_t bx = 0; bx < kBlocks; ++bx)
        for (int c = 0; c < 3; ++c)
          out[(by * kBlocks + bx) * 3 + c].push_back(
              regionMean(r.image, bx * step, by * step, (bx + 1) * step, (by + 1) * step, c));
  }
  return out;
}

// Welch's statistic for two sets of batch means; with 16 batches each the
// statistic is close to Student-t with ~15+ degrees of freedom. Over
// 16 regions x 3 channels x 3 pairs = 144 comparisons, a bound of 6 keeps the
// family-wise false alarm rate below 1e-3 (t_15 tail at 6 is ~1.2e-5 two-sided),
// while a real bias of a few standard errors anywhere is caught.
constexpr double kMaxT = 6.0;

void expectAgree(const RegionSamples& a, const RegionSamples& b, const char* what) {
  double worst = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    Moments ma = moments(a[i]), mb = moments(b[i]);
    double se = std::sqrt(ma.variance / ma.n + mb.variance / mb.n);
    if (se == 0) {
      EXPECT_DOUBLE_EQ(ma.mean, mb.mean) << what << " region " << i / 3;
      continue;
    }
    double t = std::abs(ma.mean - mb.mean) / se;
    worst = std::max(worst, t);
    EXPECT_LT(t, kMaxT) << what << ": region " << i / 3 << " channel " << i % 3 << " means "
                        << ma.mean << " vs " << mb.mean << " (standard error " << se << ")";
  }
  std::printf("%s: worst |t| = %.2f over %zu comparisons\n", what, worst, a.size());
}

TEST_F(EstimatorAgreement, CornellBoxBsdfNeeAndMisConverge) {
  scene::SceneAsset asset = scene::loadGltf(assetPath("cornell_box.gltf"));
  auto mis = renderBatches(ctx(), asset, render::Estimator::Mis, 1000);
  auto bsdf = renderBatches(ctx(), asset, render::Estimator::BsdfOnly, 2000);
  auto nee = renderBatches(ctx(), asset, render::Estimator::NeeOnly, 3000);
  expectAgree(mis, bsdf, "mis vs bsdf");
  expectAgree(mis, nee, "mis vs nee");
  expectAgree(bsdf, nee, "bsdf vs nee");

  // The comparison has power: the whole-image standard error of MIS is small
  // enough that a 5% bias in any estimator would exceed the bound.
  std::vector<double> whole;
  for (uint32_t b = 0; b < kBatches; ++b) {
    double sum = 0;
    for (size_t i = 0; i < mis.size(); i += 3) sum += mis[i][b];
    whole.push_back(sum / double(mis.size() / 3));
  }
  Moments m = moments(whole);
  EXPECT_LT(kMaxT * m.standardError() * std::sqrt(2.0), 0.05 * m.mean);
}

}  // namespace
}  // namespace qlight::test
