// Shadow rays leave a surface without hitting it again at any triangle size. A
// Lambertian floor lit by a point light, seen at grazing light angles (direct
// light only, NEE: a point light has no noise), renders the same whether the
// floor is one 1 km quad or 16 x 16 quads of 2 m around the view: the hit
// point of a huge triangle carries a rounding error that scales with its
// vertices, not with the point, and an offset scaled to the point alone lets
// shadow rays hit the floor they start on.
#include <glm/gtc/matrix_transform.hpp>

#include "engine/scene/procedural.h"
#include "tests/render/render_support.h"

namespace qlight::test {
namespace {

constexpr float kLightHeight = 0.3f;  // low: most of the view sees the light at grazing angles

scene::SceneAsset litFloor(bool oneQuad) {
  scene::SceneAsset s;
  scene::MaterialAsset m;
  m.baseColorFactor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
  m.metallicFactor = 0.0f;
  m.specularFactor = 0.0f;
  s.materials.push_back(m);
  scene::MeshAsset mesh;
  if (oneQuad) {
    const float h = 500.0f;
    scene::addQuad(mesh, {-h, 0, h}, {h, 0, h}, {h, 0, -h}, {-h, 0, -h}, 0);
  } else {
    const int n = 16;
    const float step = 2.0f, h = 0.5f * n * step;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        float x0 = -h + i * step, z0 = -h + j * step;
        scene::addQuad(mesh, {x0, 0, z0 + step}, {x0 + step, 0, z0 + step}, {x0 + step, 0, z0},
                       {x0, 0, z0}, 0);
      }
  }
  scene::addMeshAtOrigin(s, mesh);
  scene::addPointLightNode(s, 5.0f, {0.0f, kLightHeight, 0.0f});
  // 2 m up, 6 m back, looking down at the floor around the light: the view spans about
  // 1-10 m from the light, where its rays graze the floor at 2-17 degrees.
  scene::addCameraNode(s, 0.9f, {0.0f, 2.0f, 6.0f}, glm::angleAxis(-0.45f, glm::vec3(1, 0, 0)));
  scene::refreshBounds(s);
  return s;
}

class RayOffset : public GpuTest {};

TEST_F(RayOffset, HugeTrianglesDoNotShadowThemselves) {
  render::RenderSettings s = smallSettings(64, 48, 5);
  s.maxDepth = 1;  // direct light only
  s.estimator = render::Estimator::NeeOnly;
  s.russianRoulette = false;
  guiding::GuidingSettings off;
  off.enabled = false;
  auto huge = session::renderScene(ctx(), litFloor(true), s, 16, 0.0f, off).image;
  auto tiled = session::renderScene(ctx(), litFloor(false), s, 16, 0.0f, off).image;
  // Same seed, same pixel jitter, same hit points up to rounding: only self-shadowed shadow
  // rays can tell the two apart. Any pixel more than 1% darker, and the mean, are checked.
  double sumHuge = 0, sumTiled = 0;
  int darker = 0, lit = 0;
  for (size_t i = 0; i < huge.rgba.size(); i += 4) {
    double a = huge.rgba[i + 1], b = tiled.rgba[i + 1];
    if (b <= 0.0) continue;
    ++lit;
    sumHuge += a;
    sumTiled += b;
    if (a < 0.99 * b) ++darker;
  }
  ASSERT_GT(lit, 64 * 48 / 2) << "the floor should fill most of the view";
  EXPECT_EQ(darker, 0) << "of " << lit << " lit pixels";
  EXPECT_NEAR(sumHuge / sumTiled, 1.0, 1e-3);
}

}  // namespace
}  // namespace qlight::test
