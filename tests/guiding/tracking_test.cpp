// Tracking by light motion: when the door-ajar light jumps into the other room, every
// point's confidence drops at once, in the upload phase, before the jump frame's paths read
// it (so they sample by the BSDF, not toward where the light was), by
// 2^-(forgetting x distance / radius); a light that stands still forgets nothing.
// Counts stop at full confidence, so the confidence itself drops by that factor.
#include <numeric>

#include "engine/session/renderer.h"
#include "shaders/shared/guiding_types.h"
#include "tests/render/render_support.h"

namespace qlight::test {
namespace {

class Tracking : public GpuTest {};

TEST_F(Tracking, ALightJumpDropsEveryPointsConfidenceBeforeTheFrameIsTraced) {
  const scene::SceneAsset asset = gltf::loadGltf(assetPath("door_ajar_jumping_light.gltf"));
  render::RenderSettings s = smallSettings(64, 36, 3);
  s.samplesPerFrame = 1;
  double lastMeanConfidence = 0;  // over the points, after the (simulated) frame
  auto updatesAfter = [&](float forgetting, float jumpTime) {
    guiding::GuidingSettings g;
    g.forgetOnLightMove = forgetting;
    session::Renderer renderer(ctx(), asset, s, g);
    for (int f = 0; f < 12; ++f) renderer.renderFrame(0.4f * float(f));  // the light stands
    const auto before = renderer.guide()->tables().readPointUpdates();
    renderer.update(jumpTime);  // simulate, extract, upload: nothing traced yet
    const auto after = renderer.guide()->tables().readPointUpdates();
    const uint32_t strata = renderer.guide()->settings().strata();
    double confidence = 0;
    for (uint32_t u : after) confidence += shared::confidenceOf(u, g.confidenceUpdates, strata);
    lastMeanConfidence = confidence / double(renderer.guide()->stats().points);
    return std::pair{std::accumulate(before.begin(), before.end(), 0.0),
                     std::accumulate(after.begin(), after.end(), 0.0)};
  };
  const auto [rememberBefore, rememberAfter] = updatesAfter(0.0f, 6.1f);
  const auto [forgetBefore, forgetAfter] = updatesAfter(4.0f, 6.1f);
  const double confidenceAfterJump = lastMeanConfidence;
  const auto [stillBefore, stillAfter] = updatesAfter(4.0f, 5.0f);  // no jump yet at 5 s
  const double confidenceStill = lastMeanConfidence;
  EXPECT_EQ(forgetBefore, rememberBefore) << "a light that stands still forgets nothing";
  EXPECT_EQ(stillAfter, stillBefore) << "no jump, no aging";
  EXPECT_EQ(rememberAfter, rememberBefore) << "without forgetting a jump changes nothing";
  EXPECT_GT(forgetBefore, 1000.0);
  // The jump (5.3 m in a scene of radius ~4.7) is ~4.5 halvings: aged to ~5% already.
  EXPECT_LT(forgetAfter, 0.08 * forgetBefore)
      << "before " << forgetBefore << ", after " << forgetAfter;
  EXPECT_GT(forgetAfter, 0.02 * forgetBefore);
  // And so is the confidence: the update counts stop at full confidence, so a point that
  // learned for long does not keep guiding toward where the light was.
  EXPECT_GT(confidenceStill, 0.3);
  EXPECT_LT(confidenceAfterJump, 0.08 * confidenceStill) << "still " << confidenceStill;
}

}  // namespace
}  // namespace qlight::test
