// Scenes whose every material is exactly Lambertian get path pipelines without the
// microfacet code (kUseMicrofacet false: shared/bsdf.h returns the Lambertian values at
// once). They must render what the full model renders for those materials: the door
// scene with an extra, unused glossy material (which keeps the full model in) gives the
// same image, guided and learning or not.
#include <algorithm>

#include "engine/render/gpu_scene.h"
#include "tests/render/render_support.h"

namespace qlight::test {
namespace {

class LambertianPipelines : public GpuTest, public ::testing::WithParamInterface<bool> {};

scene::SceneAsset withUnusedGlossyMaterial(scene::SceneAsset asset) {
  scene::MaterialAsset glossy;
  glossy.name = "unused glossy";
  glossy.metallicFactor = 0.0f;
  glossy.roughnessFactor = 0.3f;  // specularFactor 1: a dielectric specular layer
  asset.materials.push_back(glossy);
  return asset;
}

TEST_F(LambertianPipelines, OnlyScenesWithAMicrofacetLobeKeepTheFullModel) {
  scene::SceneAsset door = gltf::loadGltf(assetPath("door_ajar.gltf"));
  EXPECT_FALSE(render::GpuScene(ctx(), door).hasMicrofacet());
  EXPECT_TRUE(render::GpuScene(ctx(), withUnusedGlossyMaterial(door)).hasMicrofacet());
  EXPECT_TRUE(
      render::GpuScene(ctx(), gltf::loadGltf(assetPath("glossy_floor.gltf"))).hasMicrofacet());
}

TEST_P(LambertianPipelines, RenderWhatTheFullModelRendersForLambertianMaterials) {
  const bool guided = GetParam();
  scene::SceneAsset lambertian = gltf::loadGltf(assetPath("door_ajar.gltf"));
  scene::SceneAsset full = withUnusedGlossyMaterial(lambertian);
  auto render = [&](const scene::SceneAsset& asset) {
    render::RenderSettings s = smallSettings(48, 32, 5);
    s.samplesPerFrame = 2;  // several frames: a guide learns between them
    guiding::GuidingSettings g;
    g.enabled = guided;
    g.pointBudget = 2048;
    g.dartPaths = 4096;
    g.seed = 5;
    return session::renderScene(ctx(), asset, s, 8, 0.0f, g);
  };
  session::OfflineRender a = render(lambertian), b = render(full);
  ASSERT_EQ(a.image.rgba.size(), b.image.rgba.size());
  // The same paths (the same random numbers go to the same choices) ...
  EXPECT_EQ(a.stats.counters.rays, b.stats.counters.rays);
  EXPECT_EQ(a.stats.counters.shadowRays, b.stats.counters.shadowRays);
  // ... and the same values, up to float rounding in the full model's lobe weights.
  double sum = 0, worst = 0;
  for (size_t i = 0; i < a.image.rgba.size(); ++i) {
    double x = a.image.rgba[i], y = b.image.rgba[i];
    sum += x;
    worst = std::max(worst, std::abs(x - y) / std::max(1e-3, std::abs(y)));
  }
  EXPECT_LT(worst, 1e-4);
  EXPECT_GT(sum, 0.0) << "not a black image";
}

INSTANTIATE_TEST_SUITE_P(Guiding, LambertianPipelines, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "Guided" : "Unguided"; });

}  // namespace
}  // namespace qlight::test
