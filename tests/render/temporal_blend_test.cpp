// Temporal blending keeps the accumulated samples at a weight: after a fade by
// k the image holds k times the old samples plus the new ones, in radiance and
// in sample count alike, so the mean stays an unbiased weighted average.
#include "engine/session/offline_render.h"
#include "engine/session/renderer.h"
#include "tests/render/render_support.h"

namespace qlight::test {
namespace {

class TemporalBlend : public GpuTest {};

TEST_F(TemporalBlend, FadeWeightsTheHistoryInRadianceAndCount) {
  scene::SceneAsset asset = gltf::loadGltf(assetPath("cornell_box.gltf"));
  render::RenderSettings s = smallSettings(16, 16, 3);
  s.samplesPerFrame = 4;
  session::Renderer renderer(ctx(), asset, s, session::disabledGuiding(), 1.0f);
  render::PathTracer& tracer = renderer.tracer();
  auto frame = [&] { renderer.renderFrame(0.0f); };
  frame();
  auto before = tracer.accumulation().readFloats(ctx());
  tracer.fadeAccumulation(0.25f);
  frame();
  auto after = tracer.accumulation().readFloats(ctx());
  for (size_t i = 0; i < after.size(); i += 4) {
    ASSERT_FLOAT_EQ(after[i + 3], 0.25f * 4.0f + 4.0f);  // samples: 1 old-equivalent + 4 new
    for (int c = 0; c < 3; ++c) ASSERT_GE(after[i + c], 0.25f * before[i + c] * (1.0f - 1e-6f));
  }
  EXPECT_EQ(tracer.accumulatedSamples(), 5u);
  EXPECT_THROW(tracer.fadeAccumulation(1.5f), std::invalid_argument);
}

}  // namespace
}  // namespace qlight::test
