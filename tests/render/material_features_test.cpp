// glTF material features end to end, on scenes whose pixels have exact answers:
// KHR_texture_transform and vertex colours on an unlit quad (an unlit surface shows exactly
// its base colour, so every pixel is known without noise), unlit surfaces ending paths,
// and a normal map tilting a Lambertian plane under a directional light.
#define GLM_ENABLE_EXPERIMENTAL
#include <glm/gtc/quaternion.hpp>
#include <glm/gtx/quaternion.hpp>

#include "engine/guiding/guiding_settings.h"
#include "engine/scene/procedural.h"
#include "engine/scene/tangents.h"
#include "tests/render/render_support.h"

namespace qlight::test {
namespace {

constexpr uint32_t kSize = 16;  // image and view: the quad fills the image exactly

// A double-sided unlit quad filling a kSize x kSize view: pixel (x, y) sees uv
// ((x + 0.5) / kSize, (y + 0.5) / kSize) at its centre (uv (0, 0) top left, as glTF).
scene::SceneAsset unlitQuadFillingTheView(scene::MaterialAsset m) {
  scene::SceneAsset s;
  m.unlit = true;
  m.doubleSided = true;
  s.materials.push_back(m);
  scene::MeshAsset mesh;
  const float h = 1.0f;
  scene::addQuad(mesh, {-h, h, 0}, {h, h, 0}, {h, -h, 0}, {-h, -h, 0}, 0);
  scene::addMeshAtOrigin(s, mesh);
  const float d = 4.0f;
  scene::addCameraNode(s, 2.0f * std::atan(h / d), {0, 0, d});
  scene::refreshBounds(s);
  return s;
}

image::LinearImage renderUnlit(const gpu::Context& ctx, const scene::SceneAsset& s,
                               uint32_t spp = 4) {
  render::RenderSettings settings = smallSettings(kSize, kSize, 3);
  settings.samplesPerFrame = 4;
  return session::renderScene(ctx, s, settings, spp, 0.0f).image;
}

glm::vec3 pixel(const image::LinearImage& img, uint32_t x, uint32_t y) {
  const float* p = &img.rgba[(size_t(y) * img.width + x) * 4];
  return {p[0], p[1], p[2]};
}

// 2x2 texels: red, green (top row), blue, white (bottom row); nearest, no sRGB.
scene::TextureAsset fourTexels() {
  scene::TextureAsset t;
  t.width = t.height = 2;
  t.rgba8 = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
  t.nearestFilter = true;
  return t;
}

struct TransformCase {
  glm::vec2 offset;
  float rotation;
  glm::vec2 scale;
};

class TextureTransform : public GpuTest, public ::testing::WithParamInterface<TransformCase> {};

// The texel every pixel shows is the one KHR_texture_transform's matrix, written out here
// from the extension's text (T * R * S, R = [[cos, sin], [-sin, cos]]), maps it to.
TEST_P(TextureTransform, EveryPixelShowsTheTexelItsTransformedUvNames) {
  const TransformCase c = GetParam();
  scene::MaterialAsset m;
  m.baseColorTexture.index = 0;
  m.baseColorTexture.offset = c.offset;
  m.baseColorTexture.rotation = c.rotation;
  m.baseColorTexture.scale = c.scale;
  scene::SceneAsset s = unlitQuadFillingTheView(m);
  s.textures.push_back(fourTexels());
  const image::LinearImage img = renderUnlit(ctx(), s);

  const glm::mat3 t(1, 0, 0, 0, 1, 0, c.offset.x, c.offset.y, 1);  // columns
  const float cs = std::cos(c.rotation), sn = std::sin(c.rotation);
  const glm::mat3 r(cs, -sn, 0, sn, cs, 0, 0, 0, 1);
  const glm::mat3 sc(c.scale.x, 0, 0, 0, c.scale.y, 0, 0, 0, 1);
  const glm::vec3 colours[4] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  int checked = 0;
  for (uint32_t y = 1; y + 1 < kSize; ++y)
    for (uint32_t x = 1; x + 1 < kSize; ++x) {
      const glm::vec2 uv((x + 0.5f) / kSize, (y + 0.5f) / kSize);
      const glm::vec3 mapped = t * r * sc * glm::vec3(uv, 1.0f);
      const glm::vec2 f = glm::fract(glm::vec2(mapped) * 2.0f);  // within a texel, repeated
      // A pixel spans 1/16 of uv (times the scale): skip those near a texel edge.
      const float margin = 0.5f * std::max(c.scale.x, c.scale.y) * 2.0f / kSize + 0.02f;
      if (std::min({f.x, 1 - f.x, f.y, 1 - f.y}) < margin) continue;
      const glm::ivec2 texel = glm::ivec2(glm::floor(glm::fract(glm::vec2(mapped)) * 2.0f));
      const glm::vec3 want = colours[texel.y * 2 + texel.x];
      const glm::vec3 got = pixel(img, x, y);
      for (int k = 0; k < 3; ++k) ASSERT_NEAR(got[k], want[k], 1e-4) << "pixel " << x << "," << y;
      ++checked;
    }
  EXPECT_GT(checked, 40);
}

INSTANTIATE_TEST_SUITE_P(OffsetsRotationsScales, TextureTransform,
                         ::testing::Values(TransformCase{{0.0f, 0.0f}, 0.0f, {1.0f, 1.0f}},
                                           TransformCase{{0.5f, 0.0f}, 0.0f, {1.0f, 1.0f}},
                                           TransformCase{{0.0f, 0.0f}, 1.5707964f, {1.0f, 1.0f}},
                                           TransformCase{{0.0f, 0.0f}, 0.0f, {2.0f, 1.0f}},
                                           TransformCase{{-0.2f, -0.1f}, 0.3f, {1.5f, 1.5f}}));

class TextureFiltering : public GpuTest, public ::testing::WithParamInterface<bool> {};

// Mipmaps chosen by the ray cone: a 64 x 64 checkerboard of single black and white texels on
// a quad filling a 16 x 16 image puts 4 x 4 texels under each pixel, so every pixel reads
// level 2, their exact mean 0.5 in linear light, even in one sample (without mipmaps a sample
// reads 0 or 1). sRGB textures are averaged in linear light, not in their encoding (which
// would show 0.21).
TEST_P(TextureFiltering, ADenseCheckerboardIsFilteredToItsLinearMean) {
  const bool srgb = GetParam();
  scene::MaterialAsset m;
  m.baseColorTexture.index = 0;
  scene::SceneAsset s = unlitQuadFillingTheView(m);
  scene::TextureAsset checker;
  checker.width = checker.height = 64;
  checker.srgb = srgb;
  for (uint32_t y = 0; y < 64; ++y)
    for (uint32_t x = 0; x < 64; ++x) {
      const uint8_t v = (x + y) % 2 ? 255 : 0;
      checker.rgba8.insert(checker.rgba8.end(), {v, v, v, 255});
    }
  s.textures.push_back(checker);
  const image::LinearImage img = renderUnlit(ctx(), s);
  for (uint32_t y = 1; y + 1 < kSize; ++y)
    for (uint32_t x = 1; x + 1 < kSize; ++x)
      ASSERT_NEAR(pixel(img, x, y).g, 0.5, 0.01) << "pixel " << x << "," << y;
}

INSTANTIATE_TEST_SUITE_P(LinearAndSrgb, TextureFiltering, ::testing::Bool());

using MaterialFeatures = GpuTest;

// COLOR_0 multiplies the base colour, interpolated across each triangle.
TEST_F(MaterialFeatures, VertexColoursMultiplyTheBaseColourAndInterpolate) {
  scene::MaterialAsset m;
  m.baseColorFactor = glm::vec4(0.5f, 1.0f, 1.0f, 1.0f);
  scene::SceneAsset s = unlitQuadFillingTheView(m);
  const glm::vec4 corner[4] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {1, 1, 1, 1}};
  s.meshes[0].colors.assign(corner, corner + 4);
  // A mesh without colours ahead of it (behind the camera): the coloured quad's attributes
  // must be found past another mesh's vertices.
  scene::MeshAsset before;
  scene::addQuad(before, {-1, -1, 9}, {1, -1, 9}, {1, 1, 9}, {-1, 1, 9}, 0);
  s.meshes.insert(s.meshes.begin(), before);
  for (scene::NodeAsset& node : s.nodes)
    if (node.mesh >= 0) ++node.mesh;
  scene::NodeAsset beforeNode;
  beforeNode.mesh = 0;
  scene::addNode(s, beforeNode);
  scene::refreshBounds(s);
  const image::LinearImage img = renderUnlit(ctx(), s, 128);
  int checked = 0;
  // Border pixels' filter footprints reach past the quad, and those next to the diagonal
  // mix both triangles: left out.
  for (uint32_t y = 1; y + 1 < kSize; ++y)
    for (uint32_t x = 1; x + 1 < kSize; ++x) {
      const float u = (x + 0.5f) / kSize, v = (y + 0.5f) / kSize;
      if (std::abs(int(x) - int(y)) <= 1) continue;
      // Triangles (p0 p1 p2) where v < u and (p0 p2 p3) where v > u, uv (0,0) (1,0) (1,1) (0,1).
      const glm::vec4 c = v < u ? (1 - u) * corner[0] + (u - v) * corner[1] + v * corner[2]
                                : (1 - v) * corner[0] + u * corner[2] + (v - u) * corner[3];
      const glm::vec3 want = glm::vec3(c) * glm::vec3(m.baseColorFactor);
      const glm::vec3 got = pixel(img, x, y);
      // The pixel averages a linear function over 128 uniformly jittered samples: its
      // centre's value give or take the samples' mean offset, whose deviation is
      // 0.29 / sqrt(128) = 0.026 pixel per axis; the colour changes by at most 1/16 per
      // pixel per axis, so 5 deviations are 5 * 0.026 * 2 / 16 = 0.016.
      for (int k = 0; k < 3; ++k) ASSERT_NEAR(got[k], want[k], 0.016) << "pixel " << x << "," << y;
      ++checked;
    }
  EXPECT_EQ(checked, int((kSize - 2) * (kSize - 2) - (3 * (kSize - 2) - 2)));
}

// Inside a closed box of unlit walls every path ends at its first hit: the image is the
// walls' colour exactly, whatever the estimator (a wall that also scattered would add light).
TEST_F(MaterialFeatures, UnlitSurfacesEmitTheirBaseColourAndScatterNothing) {
  for (render::Estimator e :
       {render::Estimator::Mis, render::Estimator::BsdfOnly, render::Estimator::NeeOnly}) {
    scene::SceneAsset s;
    scene::MaterialAsset m;
    m.baseColorFactor = glm::vec4(0.7f, 0.3f, 0.1f, 1.0f);
    m.unlit = true;
    s.materials.push_back(m);
    scene::MeshAsset mesh;
    scene::addBox(mesh, glm::mat4(1.0f), glm::vec3(1.0f), 0, /*facingInward=*/true);
    scene::addMeshAtOrigin(s, mesh);
    scene::addCameraNode(s, 1.2f, glm::vec3(0.1f, 0.2f, 0.3f));
    scene::refreshBounds(s);
    render::RenderSettings settings = smallSettings(16, 16, 5);
    settings.estimator = e;
    auto r = session::renderScene(ctx(), s, settings, 8, 0.0f);
    for (size_t i = 0; i < r.image.rgba.size(); i += 4)
      for (int k = 0; k < 3; ++k) ASSERT_NEAR(r.image.rgba[i + k], m.baseColorFactor[k], 1e-5);
  }
}

struct NormalMapCase {
  glm::vec3 mapped;  // the tangent-space normal the texture holds (unit)
  glm::vec3 toLight;
  float normalScale;
};

class NormalMap : public GpuTest, public ::testing::WithParamInterface<NormalMapCase> {};

// A Lambertian plane (normal +y, u along +x, v along -z) whose normal texture holds one
// tilted normal, under a directional light of irradiance E: L = albedo / pi * E * (n'.l),
// n' the mapped normal in the frame the test builds itself: t = +x, b = +z (image up).
TEST_P(NormalMap, APlaneShadesWithItsMappedNormal) {
  const NormalMapCase c = GetParam();
  scene::SceneAsset s;
  scene::MaterialAsset m;
  m.baseColorFactor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
  m.metallicFactor = 0.0f;
  m.specularFactor = 0.0f;  // exactly Lambertian
  m.normalTexture.index = 0;
  m.normalScale = c.normalScale;
  s.materials.push_back(m);
  scene::TextureAsset tex;
  tex.width = tex.height = 1;
  glm::vec3 decoded;
  for (int k = 0; k < 3; ++k) {
    const int code = int(std::lround((c.mapped[k] * 0.5f + 0.5f) * 255.0f));
    tex.rgba8.push_back(uint8_t(code));
    decoded[k] = code / 255.0f * 2.0f - 1.0f;
  }
  tex.rgba8.push_back(255);
  s.textures.push_back(tex);
  scene::MeshAsset mesh;
  const float r = 50.0f;
  scene::addQuad(mesh, {-r, 0, r}, {r, 0, r}, {r, 0, -r}, {-r, 0, -r}, 0);
  scene::addMeshAtOrigin(s, mesh);
  scene::generateMissingTangents(s);
  ASSERT_EQ(s.meshes[0].tangents.size(), 4u);
  EXPECT_EQ(s.meshes[0].tangents[0], glm::vec4(1, 0, 0, -1));  // dP/du = +x, mirrored v

  scene::LightAsset sun;
  sun.type = scene::LightType::Directional;
  sun.intensity = 3.0f;
  scene::NodeAsset sunNode;
  sunNode.light = int32_t(s.lights.size());
  s.lights.push_back(sun);
  // The light shines down its -z: turn -z onto -toLight.
  sunNode.local.rotation = glm::rotation(glm::vec3(0, 0, -1), -glm::normalize(c.toLight));
  scene::addNode(s, sunNode);
  scene::addCameraNode(s, 0.05f, {0, 5, 0.01f}, glm::quatLookAt(glm::vec3(0, -1, 0), {0, 0, -1}));
  scene::refreshBounds(s);

  render::RenderSettings settings = smallSettings(8, 8, 9);
  settings.maxDepth = 1;
  auto out = session::renderScene(ctx(), s, settings, 4, 0.0f);
  const glm::vec3 t(1, 0, 0), b(0, 0, 1), n(0, 1, 0);
  const glm::vec3 mapped =
      glm::normalize(decoded.x * c.normalScale * t + decoded.y * c.normalScale * b + decoded.z * n);
  const double want =
      0.8 / 3.14159265358979 * 3.0 * std::max(0.0f, glm::dot(mapped, glm::normalize(c.toLight)));
  const double unmapped = 0.8 / 3.14159265358979 * 3.0 * glm::normalize(c.toLight).y;
  const double got = regionMean(out.image, 0, 0, 8, 8, 1);
  EXPECT_NEAR(got, want, 2e-3 * want + 1e-5);
  EXPECT_GT(std::abs(want - unmapped), 0.05 * want) << "the case must tell mapped from not";
}

INSTANTIATE_TEST_SUITE_P(
    TiltsAndScales, NormalMap,
    ::testing::Values(
        // Tilted toward +u (red channel), lit from the other side: darker.
        NormalMapCase{{0.5f, 0.0f, 0.8660254f}, {-0.34f, 0.94f, 0.0f}, 1.0f},
        // Tilted toward image up (green channel, +z here), lit from +z: brighter.
        NormalMapCase{{0.0f, 0.5f, 0.8660254f}, {0.0f, 0.7071f, 0.7071f}, 1.0f},
        // normalTexture.scale doubles the tilt.
        NormalMapCase{{0.0f, 0.5f, 0.8660254f}, {0.0f, 0.7071f, 0.7071f}, 2.0f}));

// A red plane at y = 1 over a green floor, both Lambertian, under a directional light of
// irradiance 3 straight down, seen from above (image x = world x, over x in [-0.8, 0.8]).
// Direct light only (maxDepth 1): a surface lit at normal incidence shows 3 / pi.
// A Lambertian floor (y = 0, 800 units wide) of colour `floor` under a square of `plane` at
// y = 1, 2 x halfSize wide, u along +x; looked down at by a narrow camera at height `eye`.
scene::SceneAsset floorUnderPlane(glm::vec3 floorColour, scene::MaterialAsset plane, float halfSize,
                                  float eye, float yfov) {
  scene::SceneAsset s;
  scene::MaterialAsset floor;
  floor.baseColorFactor = glm::vec4(floorColour, 1.0f);
  floor.metallicFactor = 0.0f;
  floor.specularFactor = 0.0f;
  plane.metallicFactor = 0.0f;
  s.materials = {floor, plane};
  scene::MeshAsset mesh;
  const float r = 400.0f, h = halfSize;
  scene::addQuad(mesh, {-r, 0, r}, {r, 0, r}, {r, 0, -r}, {-r, 0, -r}, 0);
  scene::addQuad(mesh, {-h, 1, h}, {h, 1, h}, {h, 1, -h}, {-h, 1, -h}, 1);
  scene::addMeshAtOrigin(s, mesh);
  scene::addCameraNode(s, yfov, {0, eye, 0}, glm::quatLookAt(glm::vec3(0, -1, 0), {0, 0, -1}));
  scene::refreshBounds(s);
  return s;
}

scene::SceneAsset planeOverFloor(scene::MaterialAsset plane) {
  plane.specularFactor = 0.0f;
  plane.doubleSided = true;
  scene::SceneAsset s = floorUnderPlane({0, 1, 0}, plane, 1.0f, 5.0f, 2.0f * std::atan(0.2f));
  scene::LightAsset sun;
  sun.type = scene::LightType::Directional;
  sun.intensity = 3.0f;
  scene::NodeAsset sunNode;
  sunNode.light = 0;
  s.lights.push_back(sun);
  sunNode.local.rotation = glm::rotation(glm::vec3(0, 0, -1), glm::vec3(0, -1, 0));
  scene::addNode(s, sunNode);
  scene::refreshBounds(s);
  return s;
}

constexpr double kLitAtNormalIncidence = 3.0 / 3.14159265358979;

session::OfflineRender renderDirect(const gpu::Context& ctx, const scene::SceneAsset& s,
                                    uint32_t spp) {
  render::RenderSettings settings = smallSettings(kSize, kSize, 13);
  settings.maxDepth = 1;
  return session::renderScene(ctx, s, settings, spp, 0.0f);
}

// alphaMode MASK: where the texture's alpha (0.2 on the left half, 0.9 on the right) is below
// the cutoff 0.5 the plane is absent for camera and shadow rays alike, so the left half shows
// the lit floor and the right half the lit plane, both exactly.
TEST_F(MaterialFeatures, AlphaMaskLetsRaysAndLightThroughBelowTheCutoff) {
  scene::MaterialAsset plane;
  plane.baseColorFactor = glm::vec4(1, 0, 0, 1);
  plane.alphaMode = scene::AlphaMode::Mask;
  plane.alphaCutoff = 0.5f;
  plane.baseColorTexture.index = 0;
  scene::SceneAsset s = planeOverFloor(plane);
  scene::TextureAsset alpha;
  alpha.width = 2;
  alpha.height = 1;
  alpha.rgba8 = {255, 255, 255, 51, 255, 255, 255, 230};
  alpha.nearestFilter = true;
  s.textures.push_back(alpha);
  auto r = renderDirect(ctx(), s, 4);
  for (uint32_t y = 1; y + 1 < kSize; ++y)
    for (uint32_t x = 1; x + 1 < kSize; ++x) {
      if (x == kSize / 2 - 1 || x == kSize / 2) continue;  // the seam
      const bool left = x < kSize / 2;
      const glm::vec3 got = pixel(r.image, x, y);
      EXPECT_NEAR(got.r, left ? 0.0 : kLitAtNormalIncidence, 1e-4) << x << "," << y;
      EXPECT_NEAR(got.g, left ? kLitAtNormalIncidence : 0.0, 1e-4) << x << "," << y;
    }
}

// alphaMode BLEND as stochastic transparency: a plane of alpha 0.25 is hit by a quarter of
// the camera rays and blocks a quarter of the light, so the image is 0.25 x the lit plane
// (red) over 0.75 x the floor under 0.75 of the light (green), within the noise.
TEST_F(MaterialFeatures, AlphaBlendIsStochasticTransparencyForEveryRay) {
  scene::MaterialAsset plane;
  plane.baseColorFactor = glm::vec4(1, 0, 0, 0.25f);
  plane.alphaMode = scene::AlphaMode::Blend;
  auto r = renderDirect(ctx(), planeOverFloor(plane), 64);
  for (int c : {0, 1}) {
    std::vector<double> values;
    for (uint32_t y = 0; y < kSize; ++y)
      for (uint32_t x = 0; x < kSize; ++x) values.push_back(pixel(r.image, x, y)[c]);
    const Moments m = moments(values);
    const double want = c == 0 ? 0.25 * kLitAtNormalIncidence : 0.75 * 0.75 * kLitAtNormalIncidence;
    EXPECT_NEAR(m.mean, want, 5.0 * m.standardError() + 1e-4) << "channel " << c;
    // Sharp enough to tell a plane ignored by shadow rays (0.75 instead of 0.5625).
    EXPECT_LT(5.0 * m.standardError(), 0.1 * want) << "channel " << c;
  }
}

// KHR_materials_transmission: a smooth, thin, fully transmissive pane at y = 1 over a white
// Lambertian floor, under the uniform fallback sky (radiance 1). Shadow rays stop at the pane;
// light reaches the floor through it by scattered paths (floor -> pane -> sky, with NEE at the
// pane), each direction passing 1 - F(mu), so the floor shows
// 2 int (1 - F(mu)) mu dmu = 1 - F0 - (1 - F0) / 21 = 0.9143 (F0 0.04).
// Also with Q-guiding (learning while the image accumulates): still the same floor.
TEST_F(MaterialFeatures, AThinGlassPaneTransmitsTheSky) {
  for (auto [transmission, guided] : {std::pair{1.0f, false}, {1.0f, true}, {0.0f, false}}) {
    scene::MaterialAsset pane;
    pane.roughnessFactor = 0.0f;
    pane.transmissionFactor = transmission;
    const scene::SceneAsset s = floorUnderPlane(glm::vec3(1.0f), pane, 400.0f, 0.5f, 0.1f);
    render::RenderSettings settings = smallSettings(16, 16, 17);
    settings.maxDepth = 2;  // floor, pane, sky
    settings.samplesPerFrame = 2;
    guiding::GuidingSettings g;
    g.enabled = guided;
    auto out = session::renderScene(ctx(), s, settings, 64, 0.0f, g);
    if (guided) {
      EXPECT_GT(out.stats.guidingStats.points, 10u);
    }
    ASSERT_TRUE(out.stats.fallbackSky);
    std::vector<double> values;
    for (size_t k = 0; k < out.image.rgba.size(); k += 4) values.push_back(out.image.rgba[k + 1]);
    const Moments m = moments(values);
    if (transmission == 0.0f) {
      EXPECT_LT(m.mean, 0.01) << "an opaque pane shuts the sky out";
      continue;
    }
    const double want = 1.0 - 0.04 - 0.96 / 21.0;
    // 5 standard errors, plus 1% for the pane's GGX lobe at the roughness floor.
    EXPECT_NEAR(m.mean, want, 5.0 * m.standardError() + 0.01 * want)
        << (guided ? "guided, " : "") << "standard error " << m.standardError();
  }
}

// KHR_materials_volume: a solid block of clear glass (ior 1.5, smooth) under the uniform
// sky. Every interface passes 1 - F and reflects F, so nothing is lost: the radiance is the
// sky's, 1, in every pixel, through the block (refracted, internally reflected) as around
// it. Light that refraction lost or the 1 / eta^2 radiance scaling got wrong would show.
TEST_F(MaterialFeatures, ASolidGlassBlockInAFurnaceVanishes) {
  for (bool guided : {false, true}) {
    scene::SceneAsset s;
    scene::MaterialAsset glass;
    glass.metallicFactor = 0.0f;
    glass.roughnessFactor = 0.0f;
    glass.transmissionFactor = 1.0f;
    glass.volume = true;
    s.materials.push_back(glass);
    scene::MeshAsset mesh;
    scene::addBox(mesh, glm::mat4(1.0f), glm::vec3(1.0f, 0.6f, 0.8f), 0);
    scene::addMeshAtOrigin(s, mesh);
    scene::addCameraNode(
        s, 0.6f, {1.5f, 1.2f, 3.5f},
        glm::quatLookAt(glm::normalize(glm::vec3(-1.5f, -1.2f, -3.5f)), {0, 1, 0}));
    scene::refreshBounds(s);
    render::RenderSettings settings = smallSettings(16, 16, 19);
    settings.maxDepth = 64;
    settings.russianRoulette = true;
    settings.samplesPerFrame = 4;
    guiding::GuidingSettings g;
    g.enabled = guided;
    auto out = session::renderScene(ctx(), s, settings, 64, 0.0f, g);
    EXPECT_EQ(out.stats.counters.invalidSamples, 0u);
    std::vector<double> values;
    for (size_t k = 0; k < out.image.rgba.size(); k += 4) values.push_back(out.image.rgba[k + 1]);
    const Moments m = moments(values);
    // 5 standard errors plus 1% for the GGX lobe at the roughness floor.
    EXPECT_NEAR(m.mean, 1.0, 5.0 * m.standardError() + 0.01)
        << (guided ? "guided, " : "") << "standard error " << m.standardError();
    EXPECT_LT(5.0 * m.standardError(), 0.03);
  }
}

}  // namespace
}  // namespace qlight::test
