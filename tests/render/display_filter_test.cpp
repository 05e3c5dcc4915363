// The display filter (temporal reuse by reprojection, the a-trous denoiser) on the Cornell
// box: while the camera moves it shows a frame much closer to the converged image than the
// frame's own samples, it converges to the unfiltered accumulation once the camera is still,
// and the denoiser lowers a still frame's error (also on dim, noisy walls, where more
// samples must give a better image); the tracer's accumulation is never touched.
#include "engine/ui/display_filter.h"

#include <cstdio>

#include "engine/session/offline_render.h"
#include "engine/session/renderer.h"
#include "tests/render/render_support.h"

namespace qlight::test {
namespace {

// The bench's measure (game/bench/bench_metrics.h): mean of (x - ref)^2 / (ref^2 + 0.01).
double relativeMse(const image::LinearImage& x, const image::LinearImage& ref) {
  double sum = 0;
  size_t n = 0;
  for (size_t i = 0; i < x.rgba.size(); i += 4)
    for (int c = 0; c < 3; ++c, ++n) {
      const double d = double(x.rgba[i + c]) - ref.rgba[i + c];
      sum += d * d / (double(ref.rgba[i + c]) * ref.rgba[i + c] + 0.01);
    }
  return sum / double(n);
}

class DisplayFilterTest : public GpuTest {
 protected:
  const scene::SceneAsset asset_ = gltf::loadGltf(assetPath("cornell_box.gltf"));
  // 48x48 unguided, `spp` samples a frame.
  render::RenderSettings settings(uint32_t seed, uint32_t spp) {
    render::RenderSettings s = smallSettings(48, 48, seed);
    s.samplesPerFrame = spp;
    return s;
  }
  // 512 spp of the scene from `camera`, another seed: the converged image to compare with.
  image::LinearImage reference(const scene::SceneAsset& asset, render::RenderSettings s,
                               const render::CameraView& camera) {
    s.seed = 99;
    s.samplesPerFrame = 32;
    session::Renderer renderer(ctx(), asset, s, session::disabledGuiding(), 1.0f);
    for (int f = 0; f < 16; ++f) renderer.renderFrame(0.0f, camera);
    return renderer.tracer().readImage();
  }
  void filterFrame(ui::DisplayFilter& filter, session::Renderer& renderer,
                   const render::CameraView& camera, const ui::DisplayFilterSettings& settings) {
    ctx().submitAndWait([&](VkCommandBuffer cmd) {
      gpu::PassRecorder rec(ctx(), cmd);
      filter.record(rec, renderer.scene(), renderer.tracer().accumulation(),
                    renderer.tracer().keptOfPrevious(), camera, settings);
      rec.finish();
    });
  }
  struct Errors {
    double raw, denoised;  // relMSE of the frame's samples and of the denoised frame
  };
  // One still frame of `asset` at settings `s`, denoised with the default settings, against
  // the converged image; the tracer's accumulation must stay as it was (display only).
  Errors denoiseOneFrame(const scene::SceneAsset& asset, const render::RenderSettings& s) {
    session::Renderer renderer(ctx(), asset, s, session::disabledGuiding(), 1.0f);
    const render::CameraView camera = renderer.world().camera();
    renderer.renderFrame(0.0f, camera);
    const auto before = renderer.tracer().accumulation().readFloats(ctx());
    ui::DisplayFilter filter(ctx());
    ui::DisplayFilterSettings filterSettings;
    filterSettings.denoise = true;
    filterFrame(filter, renderer, camera, filterSettings);
    EXPECT_EQ(renderer.tracer().accumulation().readFloats(ctx()), before) << "display only";
    const image::LinearImage converged = reference(asset, s, camera);
    return {relativeMse(renderer.tracer().readImage(), converged),
            relativeMse(filter.readOutput(), converged)};
  }
};

TEST_F(DisplayFilterTest, ReusesHistoryWhileMovingAndConvergesToTheAccumulationWhenStill) {
  const render::RenderSettings s = settings(5, 1);
  session::Renderer renderer(ctx(), asset_, s, session::disabledGuiding(), 1.0f);
  const render::CameraView start = renderer.world().camera();
  auto cameraAt = [&](int frame) {  // a slow slide sideways: 2 mm a frame
    render::CameraView v = start;
    v.position += glm::normalize(glm::cross(v.forward, v.up)) * (0.002f * float(frame));
    return v;
  };
  ui::DisplayFilter filter(ctx());
  ui::DisplayFilterSettings filterSettings;  // history reuse on, no denoiser
  const int moving = 16;
  for (int f = 0; f <= moving; ++f) {
    renderer.renderFrame(0.0f, cameraAt(f));
    filterFrame(filter, renderer, cameraAt(f), filterSettings);
  }
  ASSERT_EQ(renderer.tracer().keptOfPrevious(), 0.0f) << "each moving frame restarts";
  ASSERT_EQ(renderer.tracer().accumulatedSamples(), 1u);
  const image::LinearImage raw = renderer.tracer().readImage();
  const image::LinearImage shown = filter.readOutput();
  const image::LinearImage converged = reference(asset_, s, cameraAt(moving));
  const double rawError = relativeMse(raw, converged);
  const double shownError = relativeMse(shown, converged);
  // Up to 8 frames of history: about an eighth of the 1-spp variance, plus the lag of a 2 mm
  // slide; well under half.
  std::printf("moving: relMSE of the frame's samples %.4f, shown %.4f\n", rawError, shownError);
  EXPECT_LT(shownError, 0.5 * rawError) << "raw " << rawError << ", shown " << shownError;

  // Still: the history fades (0.8 a frame) under the growing accumulation.
  for (int f = 0; f < 40; ++f) {
    renderer.renderFrame(0.0f, cameraAt(moving));
    filterFrame(filter, renderer, cameraAt(moving), filterSettings);
  }
  const image::LinearImage accumulated = renderer.tracer().readImage();
  const double difference = relativeMse(filter.readOutput(), accumulated);
  // History weight 8 x 0.8^40 ~ 1e-3 against 40 samples.
  EXPECT_LT(difference, 1e-6) << "the still image is the accumulation";
}

TEST_F(DisplayFilterTest, DenoiserLowersTheErrorOfAStillFrame) {
  const Errors e = denoiseOneFrame(asset_, settings(7, 4));
  std::printf("denoiser: relMSE %.4f -> %.4f\n", e.raw, e.denoised);
  // 0.64 of the raw error with a luminance tolerance from the sample count alone, 0.20 with
  // one from the brightness's variance.
  EXPECT_LT(e.denoised, 0.35 * e.raw) << "raw " << e.raw << ", denoised " << e.denoised;
}

// The door scene's dim, indirectly lit walls at 1 and 8 spp: where a pixel's brightness is
// mostly noise, the denoiser must average it away rather than keep bright samples apart (a
// tolerance too tight for the noise prints the kernel's holes as a lattice, and the lattice
// grew with the samples: 0.19 at 1 spp, 0.39 at 8 with a tolerance from the sample count
// alone). More samples in must give a better image out.
TEST_F(DisplayFilterTest, DenoiserAveragesTheNoiseOfDimIndirectLight) {
  const scene::SceneAsset door = gltf::loadGltf(assetPath("door_ajar.gltf"));
  double denoised[2] = {0, 0};
  const uint32_t spps[2] = {1, 8};
  for (int i = 0; i < 2; ++i) {
    render::RenderSettings s = smallSettings(96, 54, 11);
    s.samplesPerFrame = spps[i];
    const Errors e = denoiseOneFrame(door, s);
    denoised[i] = e.denoised;
    std::printf("door, %u spp: relMSE %.4f -> %.4f\n", spps[i], e.raw, e.denoised);
    EXPECT_LT(e.denoised, 0.1 * e.raw) << spps[i] << " spp";
  }
  EXPECT_LT(denoised[1], denoised[0]) << "8 spp denoised no better than 1 spp";
}

}  // namespace
}  // namespace qlight::test
