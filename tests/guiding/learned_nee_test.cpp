// Learned NEE probability: a point whose shadow rays are (nearly) all blocked samples a light
// with a probability p < 1, NEE divides by p and both MIS weights use it. The scene: a floor
// under a point light with a screen between them, open only along a thin slit, so a strip of
// floor 1.6 cm wide sees the light and the rest does not. Its cache points are wider than the
// strip: those over it learn a p between the minimum and 1, the others the minimum. The
// camera looks at the strip, which only NEE lights (a point light), so an error in NEE's
// weight 1 / p moves its pixels by as much: renders with learned NEE agree with NEE at every
// vertex within noise. Power, measured when the test was written: a 5% error in that weight
// gave a worst |t| of 5.1-5.9, just under the bound of 6 (the strip's regions have a 1.5%
// standard error); the test is sized to catch a 10% error at over 6 standard errors.
#include <algorithm>

#include "engine/scene/procedural.h"
#include "engine/session/renderer.h"
#include "shaders/shared/guiding_types.h"
#include "tests/render/agreement.h"

namespace qlight::test {
namespace {

constexpr float kSlitHalfWidth = 0.004f;  // the lit strip is twice as wide

// fov: the camera's, looking down from below the screen at the strip's middle.
scene::SceneAsset slitScene(float fov) {
  scene::SceneAsset s;
  auto lambert = [&](float albedo, float emission) {
    scene::MaterialAsset m;
    m.baseColorFactor = glm::vec4(albedo, albedo, albedo, 1.0f);
    m.metallicFactor = 0.0f;
    m.specularFactor = 0.0f;
    m.emissive = glm::vec3(emission);
    s.materials.push_back(m);
    return uint32_t(s.materials.size() - 1);
  };
  const uint32_t floorMat = lambert(0.7f, 0.0f), screenMat = lambert(0.5f, 0.0f);
  scene::MeshAsset mesh;
  const float h = 1.5f, w = kSlitHalfWidth;
  scene::addQuad(mesh, {-h, 0, h}, {h, 0, h}, {h, 0, -h}, {-h, 0, -h}, floorMat);  // faces +y
  // The screen at y = 1, two sided (a quad each way), left and right of the slit x = 0.
  for (float side : {-1.0f, 1.0f}) {
    const float x0 = side * w, x1 = side * h;
    const float lo = std::min(x0, x1), hi = std::max(x0, x1);
    scene::addQuad(mesh, {lo, 1, h}, {hi, 1, h}, {hi, 1, -h}, {lo, 1, -h}, screenMat);
    scene::addQuad(mesh, {lo, 1, -h}, {hi, 1, -h}, {hi, 1, h}, {lo, 1, h}, screenMat);
  }
  scene::addMeshAtOrigin(s, mesh);
  scene::addPointLightNode(s, 10.0f, {0.0f, 2.0f, 0.0f});
  scene::addCameraNode(s, fov, {0.0f, 0.9f, 0.0f},
                       glm::angleAxis(-glm::half_pi<float>(), glm::vec3(1, 0, 0)));
  scene::refreshBounds(s);
  return s;
}

guiding::GuidingSettings learnedNee(float minProbability, uint32_t seed) {
  guiding::GuidingSettings g;
  g.neeMinProbability = minProbability;
  g.pointBudget = 512;
  g.dartPaths = 8192;
  g.lightLearning = false;  // NEE's probability alone on top of power-based selection
  g.seed = seed;
  return g;
}

render::RenderSettings slitSettings(uint32_t seed) {
  render::RenderSettings s = smallSettings(32, 32, seed);
  s.maxDepth = 3;
  s.samplesPerFrame = 2;
  return s;
}

TEST(LearnedNeeProbability, IsOneUntilTheRaysShowTheyAreBlocked) {
  using shared::neeProbabilityOf;
  EXPECT_EQ(neeProbabilityOf(0.0f, 0.0f, 0.1f), 1.0f);      // nothing seen yet
  EXPECT_EQ(neeProbabilityOf(7.0f, 0.0f, 0.1f), 1.0f);      // too few rays to tell
  EXPECT_EQ(neeProbabilityOf(256.0f, 0.0f, 0.1f), 0.1f);    // all blocked: the minimum
  EXPECT_EQ(neeProbabilityOf(256.0f, 32.0f, 0.1f), 1.0f);   // 1 in 8 through: always
  const float some = neeProbabilityOf(256.0f, 8.0f, 0.1f);  // 1 in 32 through
  EXPECT_NEAR(some, 8.0f * 9.0f / 257.0f, 1e-6f);
  EXPECT_EQ(neeProbabilityOf(256.0f, 0.0f, 1.0f), 1.0f);  // off
}

class LearnedNee : public GpuTest {};

TEST_F(LearnedNee, PointsBehindTheScreenSkipMostShadowRays) {
  const scene::SceneAsset asset = slitScene(1.2f);  // 1.2 m of floor
  const render::RenderSettings s = slitSettings(5);
  auto shadowRaysPerPath =
      [&](float minProbability) {
        session::Renderer renderer(ctx(), asset, s, learnedNee(minProbability, 5));
        uint64_t shadow = 0, paths = 0;
        for (int f = 0; f < 24; ++f) {
          session::FrameResult r = renderer.renderFrame(0.0f);
          if (f >= 12) shadow += r.counters.shadowRays, paths += r.counters.paths;
        }
        const std::vector<float> p =
            renderer.guide()->tables().readNeeProbabilities(minProbability);
        const uint32_t points = renderer.guide()->stats().points;
        EXPECT_GT(points, 50u);
        uint32_t low = 0, between = 0;  // p near the minimum (it approaches it as rays add up)
        for (uint32_t i = 0; i < points; ++i) {
          if (p[i] <= 3.0f * minProbability)
            ++low;
          else if (p[i] < 1.0f)
            ++between;
        }
        std::printf("min %.2f: %u points, %u near the minimum, %u between\n", minProbability,
                    points, low, between);
        if (minProbability < 1.0f) {
          EXPECT_GT(low, points / 8)
              << "the floor away from the strip (the screen's top sees the light)";
          EXPECT_GT(between, 0u) << "the points over the strip see some of the light";
        }
        return double(shadow) / double(paths);
      };
  const double always = shadowRaysPerPath(1.0f), learned = shadowRaysPerPath(0.1f);
  std::printf("shadow rays per path: %.3f with NEE everywhere, %.3f learned\n", always, learned);
  EXPECT_LT(learned, 0.5 * always);
}

// A light that moves can come into the view of points that were in the dark: the counts
// forget kNeeHalvingsPerRadius times per scene radius a light moves, with tracking's
// forgetting on or off, so a move of a quarter radius leaves at most 1/256 of the window, too
// few rays to keep any point under p = 1.
class LearnedNeeAfterALightMove : public GpuTest, public ::testing::WithParamInterface<float> {};

TEST_P(LearnedNeeAfterALightMove, SendsEveryPointBackToNee) {
  const scene::SceneAsset asset = slitScene(1.2f);
  guiding::GuidingSettings g = learnedNee(0.1f, 6);
  g.forgetOnLightMove = GetParam();  // tracking's halvings per scene radius a light moves
  session::Renderer renderer(ctx(), asset, slitSettings(6), g);
  for (int f = 0; f < 16; ++f) renderer.renderFrame(0.0f);
  auto pointsUnderOne = [&] {
    const std::vector<float> p = renderer.guide()->tables().readNeeProbabilities(0.1f);
    const uint32_t points = renderer.guide()->stats().points;
    return uint32_t(std::count_if(p.begin(), p.begin() + points, [](float v) { return v < 1.0f; }));
  };
  const uint32_t before = pointsUnderOne();
  EXPECT_GT(before, renderer.guide()->stats().points / 8) << "the dark floor learned p < 1";
  renderer.guide()->noteLightMotion(0.25f);
  EXPECT_EQ(pointsUnderOne(), 0u) << before << " points were under 1 before the move";
}

INSTANTIATE_TEST_SUITE_P(TrackingOnAndOff, LearnedNeeAfterALightMove,
                         ::testing::Values(4.0f, 0.0f));

TEST_F(LearnedNee, RendersAgreeWithNeeAtEveryVertex) {
  const scene::SceneAsset asset = slitScene(0.4f);  // 36 cm of floor around the strip
  AgreementSetup setup;
  setup.size = 32;
  setup.blocks = 4;
  auto with = [&](float minProbability) {
    return [&, minProbability](uint32_t seed) {
      auto r = session::renderScene(ctx(), asset, slitSettings(seed), 48, 0.0f,
                                    learnedNee(minProbability, seed));
      EXPECT_EQ(r.stats.counters.invalidSamples, 0u);
      return r.image;
    };
  };
  const RegionSamples learned = regionMeans(setup, with(0.05f), 100);
  const RegionSamples always = regionMeans(setup, with(1.0f), 200);
  expectAgree(learned, always, "slit, learned NEE (min 0.05) vs NEE everywhere");
  // The test's power: in the strip's best measured region a 10% error is over kMaxWelchT
  // standard errors.
  double bestRelativeError = 1e30;
  for (size_t i = 0; i < learned.size(); ++i) {
    const Moments m = moments(learned[i]), n = moments(always[i]);
    if (n.mean > 1.5 * imageMeans(always).mean)  // a region of the lit strip
      bestRelativeError =
          std::min(bestRelativeError, std::sqrt(m.variance / m.n + n.variance / n.n) / n.mean);
  }
  EXPECT_LT(bestRelativeError, 0.10 / kMaxWelchT);
}

}  // namespace
}  // namespace qlight::test
