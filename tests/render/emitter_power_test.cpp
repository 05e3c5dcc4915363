// The selection power of emissive triangles from their emissive texture (emitter_power.h):
// exact on uniform textures, a zero only where every texel a triangle's filtered lookups can
// read is black, KHR_texture_transform and the wrap modes applied as the shader applies them,
// and a whole-texture quad's mean equal to the texture's. On the GPU: the triangles over
// black texels are left out of the light list and the image stays unbiased (MIS against
// scattering alone), and a scene lit only by glow maps gets the fallback sky as well.
#include "engine/render/emitter_power.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "engine/render/texture_mips.h"
#include "engine/scene/procedural.h"
#include "tests/render/agreement.h"

namespace qlight::test {
namespace {

// A grid of cells x cells quads (two triangles each) spanning uv [0, span]^2 in the xy plane,
// emissive through texture 0.
scene::SceneAsset emissiveGrid(const scene::TextureAsset& texture, uint32_t cells, float span,
                               scene::TextureBinding binding = {}) {
  scene::SceneAsset s;
  scene::MaterialAsset m;
  m.emissive = glm::vec3(2.0f, 1.0f, 0.5f);
  binding.index = 0;
  m.emissiveTexture = binding;
  s.materials.push_back(m);
  s.textures.push_back(texture);
  scene::MeshAsset mesh;
  const float step = span / float(cells);
  for (uint32_t y = 0; y < cells; ++y)
    for (uint32_t x = 0; x < cells; ++x) {
      const float u0 = x * step, u1 = (x + 1) * step, v0 = y * step, v1 = (y + 1) * step;
      const uint32_t first = uint32_t(mesh.positions.size());
      for (glm::vec2 uv :
           {glm::vec2(u0, v0), glm::vec2(u1, v0), glm::vec2(u1, v1), glm::vec2(u0, v1)}) {
        mesh.positions.push_back({uv.x, -uv.y, 0.0f});
        mesh.normals.push_back({0, 0, 1});
        mesh.uv0.push_back(uv);
      }
      for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(first + i);
      mesh.triangleMaterials.insert(mesh.triangleMaterials.end(), {0u, 0u});
    }
  s.meshes.push_back(mesh);
  return s;
}

scene::TextureAsset solid(uint32_t size, uint8_t value, bool srgb) {
  scene::TextureAsset t;
  t.width = t.height = size;
  t.srgb = srgb;
  for (uint32_t i = 0; i < size * size; ++i)
    t.rgba8.insert(t.rgba8.end(), {value, value, value, 255});
  return t;
}

void setTexel(scene::TextureAsset& t, uint32_t x, uint32_t y, uint8_t value) {
  uint8_t* p = &t.rgba8[(size_t(y) * t.width + x) * 4];
  p[0] = p[1] = p[2] = value;
}

TEST(EmitterPower, UniformTextureGivesTheFactorTimesTheTexelInLinearLight) {
  for (bool srgb : {false, true}) {
    const scene::SceneAsset s = emissiveGrid(solid(16, 128, srgb), 3, 1.0f);
    const glm::vec3 want = glm::vec3(2.0f, 1.0f, 0.5f) * render::toLinear(128, srgb);
    const auto e = render::triangleEmissions(s);
    ASSERT_EQ(e.size(), 1u);
    ASSERT_EQ(e[0].size(), 18u);
    for (const glm::vec3& v : e[0])
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(v[c], want[c], 1e-6f * want[c]) << srgb;
  }
}

TEST(EmitterPower, WithoutATextureTheFactorAloneAndNonEmittersZero) {
  scene::SceneAsset s = emissiveGrid(solid(4, 0, false), 1, 1.0f);
  s.materials[0].emissiveTexture = {};
  scene::MaterialAsset dark;
  s.materials.push_back(dark);
  s.meshes[0].triangleMaterials[1] = 1;
  const auto e = render::triangleEmissions(s);
  EXPECT_EQ(e[0][0], glm::vec3(2.0f, 1.0f, 0.5f));
  EXPECT_EQ(e[0][1], glm::vec3(0.0f));
  s.materials[0].emissive = glm::vec3(0.0f);
  EXPECT_TRUE(render::triangleEmissions(s)[0].empty());  // no emitter: no entries
}

// One bright texel in a black 64 x 64 texture under 32 x 32 cells (2 x 2 texels each, so the
// finest level is averaged): a triangle is 0 exactly when no texel within one texel of its
// UV box is bright (bilinear filtering reads one texel beyond it), else positive.
TEST(EmitterPower, ZeroExactlyWhereEveryTexelWithinReachIsBlack) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 20; ++trial) {
    const uint32_t bx = rng() % 64, by = rng() % 64;
    scene::TextureAsset t = solid(64, 0, true);
    setTexel(t, bx, by, 255);
    const scene::SceneAsset s = emissiveGrid(t, 32, 1.0f);
    const auto e = render::triangleEmissions(s);
    for (uint32_t cell = 0; cell < 32 * 32; ++cell) {
      // The cell's texels are [2x, 2x + 2) x [2y, 2y + 2); its box grown by a texel reaches
      // [2x - 1, 2x + 2] (the bright texel's centre then lies within 1.5 texels of the box).
      const int cx = int(cell % 32), cy = int(cell / 32);
      auto within = [](int texel, int c) {  // REPEAT: the reach wraps around the edges
        for (int t : {texel - 64, texel, texel + 64})
          if (t >= 2 * c - 1 && t <= 2 * c + 2) return true;
        return false;
      };
      const bool near = within(int(bx), cx) && within(int(by), cy);
      for (int half = 0; half < 2; ++half) {
        const float lum = e[0][cell * 2 + size_t(half)].g;
        if (near)
          EXPECT_GT(lum, 0.0f) << "texel " << bx << "," << by << " cell " << cx << "," << cy;
        else
          EXPECT_EQ(lum, 0.0f) << "texel " << bx << "," << by << " cell " << cx << "," << cy;
      }
    }
  }
}

double textureMean(const scene::TextureAsset& t) {
  double sum = 0.0;
  for (size_t i = 0; i < size_t(t.width) * t.height; ++i)
    sum += render::toLinear(t.rgba8[i * 4 + 1], t.srgb);
  return sum / (double(t.width) * t.height);
}

// The two triangles of a quad over the whole texture, weighted by their (equal) areas, give
// the texture's mean: a noise texture's 256 x 256 texels are averaged at the level where the
// box spans 8 texels, each of them the exact mean of 32 x 32 (0.3 / 32 apart); the diagonal's
// centres, counted in both triangles, move the mean by far less than 1%.
TEST(EmitterPower, AWholeTextureQuadEmitsTheTexturesMean) {
  std::mt19937 rng(9);
  scene::TextureAsset t = solid(256, 0, true);
  for (uint32_t y = 0; y < 256; ++y)
    for (uint32_t x = 0; x < 256; ++x) setTexel(t, x, y, uint8_t(rng() % 256));
  const auto e = render::triangleEmissions(emissiveGrid(t, 1, 1.0f));
  const double mean = 0.5 * (e[0][0].g + e[0][1].g);  // factor 1 in green
  EXPECT_NEAR(mean, textureMean(t), 0.02 * textureMean(t));
}

// Texture coordinates one repeat over give the same powers with REPEAT; KHR_texture_transform
// moves which triangle reads the bright texel; MIRRORED_REPEAT reflects and CLAMP_TO_EDGE
// clamps coordinates past 1 as the shader's sampler does.
TEST(EmitterPower, TransformAndWrapModesAsTheShaderReadsThem) {
  scene::TextureAsset t = solid(16, 0, false);
  setTexel(t, 3, 12, 255);  // u 0.22, v 0.78
  const auto base = render::triangleEmissions(emissiveGrid(t, 4, 1.0f));
  auto lit = [](const std::vector<glm::vec3>& e) {
    std::vector<bool> out;
    for (const glm::vec3& v : e) out.push_back(v.g > 0.0f);
    return out;
  };
  // Cells of 4 x 4 texels: the bright texel (3, 12) lies in cell (0, 3); texels within reach
  // of the box reach cells (1, 3), (0, 2), (1, 2) too.
  const std::vector<bool> baseLit = lit(base[0]);
  EXPECT_TRUE(baseLit[(3 * 4 + 0) * 2]);
  EXPECT_FALSE(baseLit[(0 * 4 + 3) * 2]);

  scene::TextureBinding shifted;
  shifted.offset = {1.0f, -2.0f};  // whole repeats
  const auto moved = render::triangleEmissions(emissiveGrid(t, 4, 1.0f, shifted));
  for (size_t i = 0; i < base[0].size(); ++i) EXPECT_NEAR(moved[0][i].g, base[0][i].g, 1e-6f);

  // A rotation by 90 degrees: uv' = R uv with R = [[0, 1], [-1, 0]] then offset (0, 1) maps
  // the quad onto the texture turned, u' = v, v' = 1 - u: cell (cx, cy) reads the texels of
  // the unturned cell (cy, 3 - cx). The bright texel's cell (0, 3) is now read by cell (0, 0);
  // cell (3, 3) reads the far corner's cell (3, 0).
  scene::TextureBinding turned;
  turned.rotation = 1.5707964f;
  turned.offset = {0.0f, 1.0f};
  const auto rotated = render::triangleEmissions(emissiveGrid(t, 4, 1.0f, turned));
  EXPECT_GT(rotated[0][(0 * 4 + 0) * 2].g, 0.0f);
  EXPECT_EQ(rotated[0][(3 * 4 + 3) * 2].g, 0.0f);
  EXPECT_EQ(base[0][(0 * 4 + 0) * 2].g, 0.0f);  // unturned, cell (0, 0) is far from the texel

  // uv over [0, 2]: cells past 1 read the texture mirrored (MIRRORED_REPEAT) or the edge
  // column and row (CLAMP_TO_EDGE, black here but for none: the bright texel is inside).
  scene::TextureAsset mirrored = t;
  mirrored.wrapS = mirrored.wrapT = scene::TextureWrap::MirroredRepeat;
  const auto m = render::triangleEmissions(emissiveGrid(mirrored, 8, 2.0f));
  // Cell (x, y) of the 8 x 8 grid over [0, 2]^2 reads what cell (7 - x, y) reads, mirrored
  // across u = 1, and (x, 7 - y) across v = 1.
  auto cellLit = [&](uint32_t x, uint32_t y) {
    return m[0][(y * 8 + x) * 2].g > 0.0f || m[0][(y * 8 + x) * 2 + 1].g > 0.0f;
  };
  int litCells = 0;
  for (uint32_t cy = 0; cy < 8; ++cy)
    for (uint32_t cx = 0; cx < 8; ++cx) {
      EXPECT_EQ(cellLit(cx, cy), cellLit(7 - cx, cy)) << "cell " << cx << "," << cy;
      EXPECT_EQ(cellLit(cx, cy), cellLit(cx, 7 - cy)) << "cell " << cx << "," << cy;
      litCells += cellLit(cx, cy);
    }
  EXPECT_EQ(litCells, 16);  // cells 0 and 1 in u, 2 and 3 in v (texel 3, 12), in each mirror
  scene::TextureAsset clamped = t;
  clamped.wrapS = clamped.wrapT = scene::TextureWrap::ClampToEdge;
  const auto c = render::triangleEmissions(emissiveGrid(clamped, 8, 2.0f));
  for (uint32_t cy = 0; cy < 8; ++cy)
    for (uint32_t cx = 5; cx < 8; ++cx)
      EXPECT_EQ(c[0][(cy * 8 + cx) * 2].g, 0.0f) << cx << "," << cy;
}

// A glow-mapped panel (8 x 8 cells, double-sided) a unit above a white Lambertian floor; its
// 32 x 32 texture is black but for a bright 6 x 6 block and a one-texel line, so most of its
// 128 triangles emit nothing. A black sky: only the panel lights the floor.
scene::SceneAsset glowPanelOverAFloor() {
  scene::TextureAsset t = solid(32, 0, true);
  for (uint32_t y = 4; y < 10; ++y)
    for (uint32_t x = 4; x < 10; ++x) setTexel(t, x, y, 255);
  for (uint32_t x = 0; x < 32; ++x) setTexel(t, x, 22, 200);
  scene::SceneAsset s = emissiveGrid(t, 8, 1.0f);
  s.materials[0].emissive = glm::vec3(6.0f);
  s.materials[0].doubleSided = true;
  s.materials[0].baseColorFactor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  for (glm::vec3& p : s.meshes[0].positions) p = {p.x - 0.5f, 1.0f, -p.y - 0.5f};
  for (glm::vec3& n : s.meshes[0].normals) n = {0, -1, 0};
  scene::NodeAsset panel;
  panel.mesh = 0;
  scene::addNode(s, panel);
  scene::MaterialAsset white;
  white.baseColorFactor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
  white.metallicFactor = 0.0f;
  white.specularFactor = 0.0f;
  s.materials.push_back(white);
  scene::MeshAsset floor;
  scene::addQuad(floor, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2}, {-2, 0, -2}, 1);
  scene::addMeshAtOrigin(s, floor);
  scene::addCameraNode(s, 1.0f, {0.0f, 0.5f, 2.5f});
  scene::refreshBounds(s);
  scene::EnvironmentAsset black;
  black.color = glm::vec3(0.0f);
  s.environment = black;
  return s;
}

using GlowMapLights = GpuTest;

TEST_F(GlowMapLights, BlackTrianglesLeaveTheLightListAndTheImageStaysUnbiased) {
  const scene::SceneAsset asset = glowPanelOverAFloor();
  uint32_t emitting = 0;
  const std::vector<std::vector<glm::vec3>> emissions = render::triangleEmissions(asset);
  for (const glm::vec3& e : emissions[0]) emitting += e.g > 0.0f;
  EXPECT_GT(emitting, 0u);
  EXPECT_LT(emitting, 64u);  // of 128

  AgreementSetup setup;
  auto with = [&](render::Estimator estimator) {
    return [&, estimator](uint32_t seed) {
      render::RenderSettings s = smallSettings(setup.size, setup.size, seed);
      s.estimator = estimator;
      s.maxDepth = 3;
      auto r = session::renderScene(ctx(), asset, s, 16, 0.0f);
      EXPECT_EQ(r.stats.lights, emitting);
      EXPECT_FALSE(r.stats.fallbackSky);
      EXPECT_EQ(r.stats.counters.invalidSamples, 0u);
      return r.image;
    };
  };
  auto mis = regionMeans(setup, with(render::Estimator::Mis), 1000);
  auto bsdf = regionMeans(setup, with(render::Estimator::BsdfOnly), 2000);
  expectAgree(mis, bsdf, "mis vs bsdf");
  // The comparison has power: a 5% bias in either estimator would exceed the bound.
  Moments m = imageMeans(mis);
  EXPECT_GT(m.mean, 0.0);
  EXPECT_LT(kMaxWelchT * m.standardError() * std::sqrt(2.0), 0.05 * m.mean);
}

// Glow maps are details of a model made to be seen under the viewer's light (DamagedHelmet's
// visor): alone they get the fallback sky as well, and say so; an emitter of constant emission
// (a lamp) is the scene's own light, and a chosen environment always wins.
TEST_F(GlowMapLights, OnlyGlowMapsGetTheFallbackSkyAsWell) {
  scene::SceneAsset asset = glowPanelOverAFloor();
  asset.environment.reset();
  auto stats = [&](const scene::SceneAsset& a) {
    return session::renderScene(ctx(), a, smallSettings(8, 8), 1, 0.0f).stats;
  };
  const session::RenderStats glow = stats(asset);
  EXPECT_TRUE(glow.fallbackSky);
  EXPECT_TRUE(glow.glowMapsOnly);
  EXPECT_GT(glow.lights, 1u);  // the panel's emitting triangles and the sky

  scene::SceneAsset lamp = asset;
  lamp.materials[0].emissiveTexture = {};
  const session::RenderStats lit = stats(lamp);
  EXPECT_FALSE(lit.fallbackSky);
  EXPECT_FALSE(lit.glowMapsOnly);

  scene::SceneAsset chosen = asset;
  scene::EnvironmentAsset sky;
  sky.color = glm::vec3(0.5f);
  chosen.environment = sky;
  EXPECT_FALSE(stats(chosen).fallbackSky);
}

}  // namespace
}  // namespace qlight::test
