// The default glTF material as the specification defines it, end to end: a
// large plane of one material under the uniform fallback sky (radiance 1, no
// other light) reflects its directional albedo toward the camera, which the
// test integrates from the specification's formula (tests/support/
// gltf_reference_brdf.h), not from the renderer's BSDF code. The plane is
// flat, so no light comes back to it: one bounce is the whole answer.
#include <glm/gtc/quaternion.hpp>

#include "engine/scene/procedural.h"
#include "tests/render/render_support.h"
#include "tests/support/gltf_reference_brdf.h"

namespace qlight::test {
namespace {

struct SkyPlaneCase {
  float baseColor;
  float metallic;
  float roughness;
  float viewDegrees;  // the camera's angle from the plane's normal
};

scene::SceneAsset skyLitPlane(const SkyPlaneCase& c) {
  scene::SceneAsset s;
  scene::MaterialAsset m;  // glTF defaults otherwise: specular layer on, not double-sided
  m.baseColorFactor = glm::vec4(glm::vec3(c.baseColor), 1.0f);
  m.metallicFactor = c.metallic;
  m.roughnessFactor = c.roughness;
  s.materials.push_back(m);
  scene::MeshAsset mesh;
  const float r = 100.0f;
  scene::addQuad(mesh, {-r, 0, r}, {r, 0, r}, {r, 0, -r}, {-r, 0, -r}, 0);
  scene::addMeshAtOrigin(s, mesh);
  float t = glm::radians(c.viewDegrees);
  glm::vec3 eye = 10.0f * glm::vec3(std::sin(t), std::cos(t), 0.0f);
  // A narrow view: every pixel sees the plane within 0.6 degrees of viewDegrees.
  scene::addCameraNode(s, 0.02f, eye, glm::quatLookAt(-glm::normalize(eye), {0, 0, 1}));
  scene::refreshBounds(s);
  return s;
}

class SkyLitPlane : public GpuTest, public ::testing::WithParamInterface<SkyPlaneCase> {};

TEST_P(SkyLitPlane, ReflectsTheSpecificationsAlbedo) {
  SkyPlaneCase c = GetParam();
  render::RenderSettings s = smallSettings(16, 16, 11);
  s.estimator = render::Estimator::Mis;
  s.maxDepth = 1;
  auto r = session::renderScene(ctx(), skyLitPlane(c), s, 64, 0.0f);
  ASSERT_TRUE(r.stats.fallbackSky) << "the plane must be lit by the fallback sky alone";
  EXPECT_EQ(r.stats.counters.invalidSamples, 0u);
  std::vector<double> pixels;
  for (size_t i = 0; i < r.image.rgba.size(); i += 4) pixels.push_back(r.image.rgba[i + 1]);
  Moments m = moments(pixels);
  double expected =
      gltfReferenceAlbedo(c.baseColor, c.metallic, c.roughness, glm::radians(c.viewDegrees));
  // 5 standard errors, plus 0.2% for the spread of view angles over the image.
  EXPECT_NEAR(m.mean, expected, 5.0 * m.standardError() + 2e-3 * expected)
      << "standard error " << m.standardError();
  // Sharp enough to see the old diffuse lobe's 4-11% loss.
  EXPECT_LT(5.0 * m.standardError() + 2e-3 * expected, 0.02 * expected);
}

INSTANTIATE_TEST_SUITE_P(DefaultMaterials, SkyLitPlane,
                         ::testing::Values(SkyPlaneCase{0.5f, 0.0f, 1.0f, 0.0f},
                                           SkyPlaneCase{0.5f, 0.0f, 1.0f, 60.0f},
                                           SkyPlaneCase{0.8f, 0.0f, 0.4f, 45.0f},
                                           SkyPlaneCase{0.9f, 1.0f, 0.5f, 30.0f}));

}  // namespace
}  // namespace qlight::test
