// Degenerate input renders as if it were sound: zero-area triangles (three collinear
// points, two equal vertices) as if absent, a zero-area emissive triangle too (no power:
// never a light sample with an infinite pdf), zero and NaN vertex normals as the geometric
// normal, denormal coordinates as zeros. The image is finite, no sample is rejected, and it
// matches the sound scene within the noise of the two renders.
#include <cmath>

#include "engine/scene/procedural.h"
#include "tests/render/render_support.h"

namespace qlight::test {
namespace {

scene::SceneAsset room(bool withDegenerates) {
  scene::SceneAsset s;
  scene::MaterialAsset white;
  white.baseColorFactor = glm::vec4(0.7f, 0.7f, 0.7f, 1.0f);
  white.metallicFactor = 0.0f;
  s.materials.push_back(white);
  scene::MaterialAsset lamp = white;
  lamp.emissive = glm::vec3(10.0f);
  s.materials.push_back(lamp);
  scene::MeshAsset mesh;
  scene::addBox(mesh, glm::mat4(1.0f), {1.0f, 1.0f, 1.0f}, 0, true);  // a closed room
  scene::addQuad(mesh, {-0.2f, 0.99f, 0.2f}, {0.2f, 0.99f, 0.2f}, {0.2f, 0.99f, -0.2f},
                 {-0.2f, 0.99f, -0.2f}, 1);  // ceiling lamp, facing down
  auto triangle = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 n, uint32_t material) {
    const uint32_t base = uint32_t(mesh.positions.size());
    for (glm::vec3 p : {a, b, c}) {
      mesh.positions.push_back(p);
      mesh.normals.push_back(n);
      mesh.uv0.push_back(glm::vec2(0.0f));
    }
    for (uint32_t i = 0; i < 3; ++i) mesh.indices.push_back(base + i);
    mesh.triangleMaterials.push_back(material);
  };
  // Two floor tiles just above the floor, with zero and NaN normals in the degenerate scene
  // (unit normals in the clean one), and a small one at denormal coordinates (zeros).
  const float nan = std::nanf("");
  const glm::vec3 up(0, 1, 0);
  triangle({-0.5f, -0.99f, 0.5f}, {0.5f, -0.99f, 0.5f}, {0.0f, -0.99f, -0.5f},
           withDegenerates ? glm::vec3(0.0f) : up, 0);
  triangle({-0.5f, -0.98f, 0.6f}, {0.5f, -0.98f, 0.6f}, {0.0f, -0.98f, -0.4f},
           withDegenerates ? glm::vec3(nan) : up, 0);
  const float tiny = withDegenerates ? 1e-40f : 0.0f;
  triangle({tiny, -0.97f, tiny}, {0.2f, -0.97f, tiny}, {tiny, -0.97f, 0.2f}, up, 0);
  if (withDegenerates) {  // zero-area triangles, one of them emissive
    triangle({-0.5f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, {0.5f, 0.0f, 0.0f}, up, 0);  // collinear
    triangle({0.3f, -0.5f, 0.1f}, {0.3f, -0.5f, 0.1f}, {0.6f, -0.5f, 0.4f}, up, 0);
    triangle({-0.3f, 0.5f, 0.0f}, {0.0f, 0.5f, 0.0f}, {0.3f, 0.5f, 0.0f}, -up, 1);
  }
  scene::addMeshAtOrigin(s, mesh);
  scene::addCameraNode(s, 1.2f, {0.0f, 0.0f, 0.9f});
  scene::refreshBounds(s);
  return s;
}

class DegenerateInput : public GpuTest {};

TEST_F(DegenerateInput, RendersAsTheSoundScene) {
  render::RenderSettings s = smallSettings(32, 32, 11);
  guiding::GuidingSettings g;  // guided, learning: the Q tables see these vertices too
  auto clean = session::renderScene(ctx(), room(false), s, 64, 0.0f, g);
  auto degenerate = session::renderScene(ctx(), room(true), s, 64, 0.0f, g);
  EXPECT_EQ(degenerate.stats.counters.invalidSamples, 0u);
  double sumClean = 0, sumDegenerate = 0;
  for (size_t i = 0; i < clean.image.rgba.size(); i += 4) {
    ASSERT_TRUE(std::isfinite(degenerate.image.rgba[i + 1])) << "pixel " << i / 4;
    sumClean += clean.image.rgba[i + 1];
    sumDegenerate += degenerate.image.rgba[i + 1];
  }
  // The two means differ by noise only: 64 spp over 1024 pixels of a closed, evenly lit
  // room leave ~0.3% standard error per image; 2% is ~5 sigma of the difference.
  EXPECT_NEAR(sumDegenerate / sumClean, 1.0, 0.02);
}

}  // namespace
}  // namespace qlight::test
