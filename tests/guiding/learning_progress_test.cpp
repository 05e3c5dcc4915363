// Learning works: in the door scene without NEE and Russian roulette (D&K's
// setting), the share of paths that reach the light by a scattered ray rises
// over the first frames and ends far above unguided path tracing, and paths
// reach the light sooner.
#include <numeric>

#include "tests/render/render_support.h"

namespace qlight::test {
namespace {

class LearningProgress : public GpuTest {};

double meanOf(const std::vector<double>& v, size_t begin, size_t end) {
  return std::accumulate(v.begin() + begin, v.begin() + end, 0.0) / double(end - begin);
}

TEST_F(LearningProgress, DoorSceneEmitterHitsRiseAndPathsShorten) {
  scene::SceneAsset asset = gltf::loadGltf(assetPath("door_ajar.gltf"));
  render::RenderSettings s = smallSettings(160, 90, 3);
  s.estimator = render::Estimator::BsdfOnly;
  s.russianRoulette = false;
  s.maxDepth = 12;
  s.samplesPerFrame = 1;
  const uint32_t frames = 20;
  auto unguided = session::renderScene(ctx(), asset, s, frames, 0.0f);
  guiding::GuidingSettings g;
  g.pointBudget = 8192;
  auto guided = session::renderScene(ctx(), asset, s, frames, 0.0f, g);

  const auto& share = guided.stats.emitterHitShareByFrame;
  const auto& length = guided.stats.pathLengthByFrame;
  double unguidedShare = meanOf(unguided.stats.emitterHitShareByFrame, 0, frames);
  double firstFrames = meanOf(share, 0, 2);
  double lastFrames = meanOf(share, frames - 8, frames);
  double unguidedLength = meanOf(unguided.stats.pathLengthByFrame, 0, frames);
  double guidedLength = meanOf(length, frames - 8, frames);
  std::printf(
      "emitter hit share: unguided %.5f, guided first frames %.5f, last frames %.5f (%.1fx)\n",
      unguidedShare, firstFrames, lastFrames, lastFrames / unguidedShare);
  std::printf("mean path length: unguided %.3f, guided last frames %.3f (%.0f%% shorter)\n",
              unguidedLength, guidedLength, 100.0 * (1.0 - guidedLength / unguidedLength));
  // 14k paths a frame: unguided reaches the light ~200 times over 20 frames,
  // so a 3x margin is far beyond its Poisson noise (~10%).
  EXPECT_GT(unguidedShare, 0.0);
  EXPECT_GT(lastFrames, 3.0 * unguidedShare);
  EXPECT_GT(lastFrames, 2.0 * firstFrames);
  EXPECT_LT(guidedLength, unguidedLength);
}

}  // namespace
}  // namespace qlight::test
