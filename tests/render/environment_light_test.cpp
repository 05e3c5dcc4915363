// The environment light end to end: a map or uniform sky lighting a Lambertian plane gives
// the irradiance integrated from the map, for NEE alone, scattering alone, their MIS and with
// guiding; an albedo-1 object under a uniform sky is invisible (the furnace); rotation turns
// the lighting about +Y; the user's choice replaces the fallback sky.
#include <cstdio>

#include "engine/render/gpu_scene.h"
#include "engine/session/renderer.h"
#include "shaders/shared/environment.h"
#include "tests/render/environment_scenes.h"

namespace qlight::test {
namespace {

class EnvironmentLight : public GpuTest {};

struct ChannelMoments {
  Moments c[3];
};

// Every pixel shares the expectation, so their spread gives the standard error of the mean.
ChannelMoments pixelMoments(const image::LinearImage& img) {
  ChannelMoments m;
  for (int c = 0; c < 3; ++c) {
    std::vector<double> v;
    for (size_t i = 0; i < img.rgba.size(); i += 4) v.push_back(img.rgba[i + c]);
    m.c[c] = moments(v);
  }
  return m;
}

void expectRadiance(const image::LinearImage& img, glm::dvec3 expected, const char* what) {
  ChannelMoments m = pixelMoments(img);
  for (int c = 0; c < 3; ++c) {
    double se = m.c[c].standardError();
    EXPECT_NEAR(m.c[c].mean, expected[c], 5.0 * se + 1e-4 * expected[c])
        << what << " channel " << c << " standard error " << se;
    // The test can tell: a 5% error would be far outside the tolerance.
    EXPECT_LT(5.0 * se, 0.05 * expected[c]) << what << " channel " << c;
    std::printf("%s channel %d: %.5f expected %.5f (%+.2f standard errors)\n", what, c, m.c[c].mean,
                expected[c], (m.c[c].mean - expected[c]) / se);
  }
}

session::OfflineRender render(
    const gpu::Context& ctx, const scene::SceneAsset& asset, render::Estimator estimator,
    uint32_t spp, uint32_t size = 48,
    const guiding::GuidingSettings& guiding = session::disabledGuiding()) {
  render::RenderSettings s = smallSettings(size, size, 3);
  s.estimator = estimator;
  s.maxDepth = 8;
  auto r = session::renderScene(ctx, asset, s, spp, 0.0f, guiding);
  EXPECT_EQ(r.stats.counters.invalidSamples, 0u);
  EXPECT_FALSE(r.stats.fallbackSky);
  return r;
}

// A plane of albedo a under uniform radiance L (a map, or the uniform --sky colour) reflects
// a L: it sees the whole upper hemisphere and nothing else.
TEST_F(EnvironmentLight, UniformSkyLightsAPlaneAtAlbedoTimesL) {
  const glm::vec3 l(0.6f, 1.0f, 1.4f);
  const float albedo = 0.7f;
  scene::SceneAsset asset = upwardPlane(albedo);
  asset.environment = uniformMap(16, 8, l);
  expectRadiance(render(ctx(), asset, render::Estimator::Mis, 16).image,
                 glm::dvec3(l) * double(albedo), "uniform map");
  scene::EnvironmentAsset sky;
  sky.color = l / 2.0f;
  sky.strength = 2.0f;
  asset.environment = sky;
  expectRadiance(render(ctx(), asset, render::Estimator::Mis, 16).image,
                 glm::dvec3(l) * double(albedo), "uniform sky colour");
}

// The environment furnace: an open box of albedo 1 under a uniform sky is invisible, every
// pixel L, whatever the number of bounces (Russian roulette ends the paths).
TEST_F(EnvironmentLight, AlbedoOneOpenBoxUnderAUniformSkyIsInvisible) {
  scene::SceneAsset asset;
  asset.materials.push_back(lambertian(1.0f));
  scene::MeshAsset mesh;
  scene::addBox(mesh, glm::mat4(1.0f), glm::vec3(1.0f, 0.5f, 1.0f), 0, /*facingInward=*/true,
                scene::kBoxAllFaces & ~scene::kBoxMaxY);
  scene::addMeshAtOrigin(asset, mesh);
  scene::addCameraNode(asset, 1.0f, glm::vec3(0.3f, 1.2f, 0.2f),
                       glm::angleAxis(-1.2f, glm::vec3(1, 0, 0)));
  scene::refreshBounds(asset);
  scene::EnvironmentAsset sky;
  sky.color = glm::vec3(0.5f, 0.8f, 1.1f);
  asset.environment = sky;
  render::RenderSettings s = smallSettings(32, 32, 5);
  s.maxDepth = 1024;
  auto r = session::renderScene(ctx(), asset, s, 32, 0.0f);
  EXPECT_EQ(r.stats.counters.invalidSamples, 0u);
  expectRadiance(r.image, glm::dvec3(sky.color), "albedo-1 open box");
}

struct PlaneCase {
  const char* name;
  render::Estimator estimator;
  bool guided;
  bool lightLearning;
};

class SkyWithSunOnAPlane : public EnvironmentLight,
                           public ::testing::WithParamInterface<PlaneCase> {};

// A sky with a sun, rotated (which a plane facing up does not see): the plane's radiance is
// albedo / pi times the irradiance summed from the map's pixels in the test. An emitter under
// the plane, facing away, competes for NEE's light choice (and adds nothing).
TEST_P(SkyWithSunOnAPlane, RadianceIsAlbedoOverPiTimesTheMapsIrradiance) {
  PlaneCase c = GetParam();
  const float albedo = 0.6f;
  scene::SceneAsset asset = upwardPlane(albedo, /*emitterBelow=*/true);
  asset.environment = skyWithSun();
  asset.environment->rotationDegrees = 40.0f;
  asset.environment->strength = 1.5f;
  guiding::GuidingSettings g = session::disabledGuiding();
  if (c.guided) {
    g = guiding::GuidingSettings{};
    g.lightLearning = c.lightLearning;
  }
  auto r = render(ctx(), asset, c.estimator, c.estimator == render::Estimator::BsdfOnly ? 512 : 32,
                  48, g);
  expectRadiance(r.image, irradianceFacingUp(*asset.environment) * double(albedo) / kPiD, c.name);
}

INSTANTIATE_TEST_SUITE_P(
    Estimators, SkyWithSunOnAPlane,
    ::testing::Values(PlaneCase{"mis", render::Estimator::Mis, false, false},
                      PlaneCase{"bsdf", render::Estimator::BsdfOnly, false, false},
                      PlaneCase{"nee", render::Estimator::NeeOnly, false, false},
                      PlaneCase{"guided", render::Estimator::Mis, true, false},
                      PlaneCase{"guided_light_learning", render::Estimator::Mis, true, true}),
    [](const ::testing::TestParamInfo<PlaneCase>& i) { return std::string(i.param.name); });

// A sun on the horizon at -Z unrotated: it lights neither face of the box the camera sees
// (+Z on the left, +X on the right); turned by 180 degrees it lights +Z; by -90, +X.
TEST_F(EnvironmentLight, RotationTurnsTheLightingAboutUp) {
  scene::SceneAsset asset = boxSeenFromCorner();
  scene::EnvironmentAsset env = uniformMap(32, 16, glm::vec3(0.02f));
  for (uint32_t row = 7; row < 9; ++row)
    for (uint32_t col = 15; col < 17; ++col) env.radiance[row * 32 + col] = glm::vec3(50.0f);
  const uint32_t size = 48;
  auto faces = [&](float degrees) {
    env.rotationDegrees = degrees;
    asset.environment = env;
    image::LinearImage img = render(ctx(), asset, render::Estimator::Mis, 16, size).image;
    // Blocks well inside each face: left of centre +Z, right of centre +X.
    double left = regionMean(img, size * 3 / 16, size * 6 / 16, size * 6 / 16, size * 10 / 16, 1);
    double right =
        regionMean(img, size * 10 / 16, size * 6 / 16, size * 13 / 16, size * 10 / 16, 1);
    std::printf("rotation %g: +Z face %.4f, +X face %.4f\n", degrees, left, right);
    return std::pair{left, right};
  };
  auto [zUnlit, xUnlit] = faces(0.0f);
  auto [zLit, xSide] = faces(180.0f);
  auto [zSide, xLit] = faces(-90.0f);
  EXPECT_GT(zLit, 10.0 * zUnlit);
  EXPECT_GT(zLit, 10.0 * xSide);
  EXPECT_GT(xLit, 10.0 * xUnlit);
  EXPECT_GT(xLit, 10.0 * zSide);
}

// The user's environment lights the scene next to its emitters (no fallback), as one light
// per tile of its map; without one a scene with no light gets the fallback sky; a black
// environment is no light at all.
TEST_F(EnvironmentLight, TheUsersChoiceReplacesTheFallbackSky) {
  scene::SceneAsset box = gltf::loadGltf(assetPath("cornell_box.gltf"));
  scene::SceneAsset plane = upwardPlane(0.5f);
  render::RenderSettings s = smallSettings(8, 8);
  auto lights = [&](const scene::SceneAsset& a) {
    session::Renderer r(ctx(), a, s, session::disabledGuiding());
    return std::tuple{r.scene().lightCount(), r.scene().usesFallbackSky(),
                      r.scene().hasEnvironment()};
  };
  auto [boxLights, boxFallback, boxEnv] = lights(box);
  EXPECT_FALSE(boxFallback);
  EXPECT_FALSE(boxEnv);
  box.environment = skyWithSun();
  const uint32_t tiles = shared::kEnvironmentTilesX * shared::kEnvironmentTilesY;
  EXPECT_EQ(lights(box), std::tuple(boxLights + tiles, false, true));
  EXPECT_EQ(lights(plane), std::tuple(1u, true, false));
  plane.environment = scene::EnvironmentAsset{};
  plane.environment->strength = 0.0f;
  EXPECT_EQ(lights(plane), std::tuple(0u, false, false));
}

}  // namespace
}  // namespace qlight::test
