// What Q learns from returns, against a CPU reference on a tiny scene: a large
// floor under a large ceiling, a point light between them, the camera looking
// at a small patch of floor around the origin. With two bounces (max depth 2)
// and BSDF sampling only, the return of a floor vertex's direction w is the
// NEE estimate at the ceiling point y it hits, exactly:
//   g(w) = (rho_c / pi) I cos(theta_y) / |light - y|^2
// (the floor vertex's own NEE is not part of it; y's scattered ray reaches
// nothing that gives light). With the learning rate 1 / (1 + n), Q of stratum
// k is the mean of its targets, whose expectation is g averaged over the
// stratum with the cosine density of the samples. D&K's one-step target cannot
// learn this scene at all: a point light is never hit, and the ceiling's Q
// never learns what NEE finds there.
#include <glm/gtc/matrix_transform.hpp>

#include "engine/guiding/cache_point.h"
#include "engine/scene/procedural.h"
#include "engine/session/renderer.h"
#include "shaders/shared/sampling.h"
#include "shaders/shared/strata.h"
#include "tests/render/render_support.h"

namespace qlight::test {
namespace {

constexpr float kCeiling = 4.0f;     // ceiling height
constexpr float kLightY = 2.0f;      // point light height, above the origin
constexpr float kIntensity = 20.0f;  // candela
constexpr float kRhoCeiling = 0.8f;
constexpr float kRhoFloor = 0.5f;
// Planes of kTiles x kTiles quads: one huge triangle pair loses shadow rays to
// self-intersection at grazing angles (its hit points are interpolated from
// vertices 100s of metres away). Directions past the ceiling's edge escape.
constexpr float kHalfSize = 32.0f;
constexpr int kTiles = 32;
constexpr uint32_t kRows = 8, kCols = 4;  // strata

scene::SceneAsset floorCeilingPointLight(float ceilingGlow = 0.0f) {
  scene::SceneAsset s;
  auto lambert = [&](float albedo) {
    scene::MaterialAsset m;
    m.baseColorFactor = glm::vec4(albedo, albedo, albedo, 1.0f);
    m.metallicFactor = 0.0f;
    m.specularFactor = 0.0f;  // exactly Lambertian
    s.materials.push_back(m);
    return uint32_t(s.materials.size() - 1);
  };
  const uint32_t floorMat = lambert(kRhoFloor), ceilingMat = lambert(kRhoCeiling);
  s.materials[ceilingMat].emissive = glm::vec3(ceilingGlow);
  scene::MeshAsset mesh;
  const float step = 2.0f * kHalfSize / kTiles;
  for (int i = 0; i < kTiles; ++i)
    for (int j = 0; j < kTiles; ++j) {
      float x0 = -kHalfSize + i * step, x1 = x0 + step;
      float z0 = -kHalfSize + j * step, z1 = z0 + step;
      scene::addQuad(mesh, {x0, 0, z1}, {x1, 0, z1}, {x1, 0, z0}, {x0, 0, z0}, floorMat);  // +y
      scene::addQuad(mesh, {x0, kCeiling, z0}, {x1, kCeiling, z0}, {x1, kCeiling, z1},
                     {x0, kCeiling, z1}, ceilingMat);  // faces -y
    }
  scene::addMeshAtOrigin(s, mesh);
  scene::addPointLightNode(s, kIntensity, {0.0f, kLightY, 0.0f});
  // A ~1 cm patch of floor, under the light, looking straight down.
  scene::addCameraNode(s, 0.01f, {0.0f, 1.0f, 0.0f},
                       glm::angleAxis(-glm::half_pi<float>(), glm::vec3(1, 0, 0)));
  scene::refreshBounds(s);
  return s;
}

// The return of direction w (world, w.y > 0) from the origin.
double returnOf(glm::dvec3 w) {
  glm::dvec3 y = w * (double(kCeiling) / w.y);
  if (std::abs(y.x) > kHalfSize || std::abs(y.z) > kHalfSize) return 0.0;  // escapes
  glm::dvec3 d = glm::dvec3(0.0, kLightY, 0.0) - y;
  double dist2 = glm::dot(d, d);
  double cosY = -d.y / std::sqrt(dist2);  // the ceiling's normal is -y
  return kRhoCeiling / glm::pi<double>() * kIntensity * cosY / dist2;
}

struct StratumReference {
  double mean = 0, variance = 0, probability = 0;  // of the return; chance of the stratum
};

// Moments of the return over stratum k under cosine sampling, by midpoint quadrature.
StratumReference reference(uint32_t k, uint32_t rows, uint32_t cols,
                           const shared::TangentFrame& frame) {
  constexpr int kN = 256;
  double sum = 0, sum2 = 0, weight = 0;
  for (int i = 0; i < kN; ++i)
    for (int j = 0; j < kN; ++j) {
      glm::vec2 u((i + 0.5f) / kN, (j + 0.5f) / kN);
      glm::vec3 local = shared::stratumDirectionUniform(k, u, rows, cols);
      glm::dvec3 w = glm::dvec3(shared::worldFromLocal(frame, local));
      double c = local.z;  // uniform samples weighted by the cosine density
      double g = returnOf(w);
      sum += c * g;
      sum2 += c * g * g;
      weight += c;
    }
  StratumReference r;
  r.mean = sum / weight;
  r.variance = sum2 / weight - r.mean * r.mean;
  r.probability = shared::stratumCosineIntegral(k, rows, cols) / glm::pi<double>();
  return r;
}

// 32x32 pixels, two bounces (the camera's vertex and the ceiling's), no Russian roulette.
render::RenderSettings twoBounces(uint32_t samplesPerFrame) {
  render::RenderSettings s = smallSettings(32, 32, 3);
  s.samplesPerFrame = samplesPerFrame;
  s.maxDepth = 2;
  s.russianRoulette = false;
  return s;
}

class LearningTarget : public GpuTest {
 protected:
  struct Learned {
    std::vector<float> q;
    glm::vec3 pointPosition, pointNormal;
    uint64_t targets = 0;  // camera-vertex targets in all
  };

  Learned learn(guiding::LearningTarget target, int frames, float ceilingGlow = 0.0f) {
    scene::SceneAsset asset = floorCeilingPointLight(ceilingGlow);
    render::RenderSettings s = twoBounces(8);
    guiding::GuidingSettings g;
    g.target = target;
    g.rows = kRows;
    g.cols = kCols;
    g.selectProbability = 0.0f;  // BSDF (cosine) sampling only: the reference's density
    g.alphaMax = 1.0f;           // 1 / (1 + n): Q is the mean of all its targets
    g.alphaMin = 1e-7f;
    g.pointBudget = 16384;
    g.dartPaths = 2048;  // few darts: the camera's patch gets its point from a camera spawn
    g.rejectionMin = 0.05f;
    session::Renderer renderer(ctx(), asset, s, g, 1.0f);
    for (int f = 0; f < frames; ++f) renderer.renderFrame(0.0f);
    // The floor point nearest the camera's patch: the one its vertices found.
    const auto& points = renderer.world().registry().storage<guiding::CachePoint>();
    float best = 1e30f;
    Learned out;
    uint32_t slot = 0;
    for (const guiding::CachePoint& p : points.values()) {
      float d = glm::length(p.position);
      if (p.normal.y > 0.99f && d < best) {
        best = d;
        slot = p.slot;
        out.pointPosition = p.position;
        out.pointNormal = p.normal;
      }
    }
    EXPECT_LT(best, 0.05f) << "no cache point at the camera's patch";
    out.q = renderer.guide()->readQ(slot);
    out.targets = uint64_t(frames) * s.samplesPerFrame * s.width * s.height;
    return out;
  }
};

TEST_F(LearningTarget, ReturnsMatchTheCpuReferencePerStratum) {
  Learned l = learn(guiding::LearningTarget::Returns, 12);
  const shared::TangentFrame frame = shared::frameFromNormal(l.pointNormal);
  ASSERT_EQ(l.q.size(), kRows * kCols);
  guiding::GuidingSettings defaults;
  for (uint32_t k = 0; k < kRows * kCols; ++k) {
    StratumReference r = reference(k, kRows, kCols, frame);
    // The mean of ~N P_k targets: 5 standard errors, plus 1% for the patch's spread around
    // the origin (the return changes by < 1% per cm there). No Q goes below the floor.
    double n = double(l.targets) * r.probability;
    double tolerance = 5.0 * std::sqrt(r.variance / n) + 0.01 * r.mean;
    EXPECT_NEAR(l.q[k], std::max<double>(r.mean, defaults.qFloor), tolerance)
        << "stratum " << k << " (row " << k / kCols << ")";
  }
}

// The scene itself renders as the analytic two-bounce value: direct light at the origin plus
// the floor's albedo times the cosine-weighted mean return.
TEST_F(LearningTarget, SceneRendersItsAnalyticValue) {
  scene::SceneAsset asset = floorCeilingPointLight();
  render::RenderSettings s = twoBounces(64);
  guiding::GuidingSettings g;
  g.enabled = false;
  auto r = session::renderScene(ctx(), asset, s, 512, 0.0f, g);
  std::vector<double> px;
  for (size_t i = 0; i < r.image.rgba.size(); i += 4) px.push_back(r.image.rgba[i + 1]);
  Moments m = moments(px);
  const shared::TangentFrame frame = shared::frameFromNormal(glm::vec3(0, 1, 0));
  double indirect = 0;
  for (uint32_t k = 0; k < 64; ++k) {
    StratumReference ref = reference(k, 64, 1, frame);
    indirect += ref.probability * ref.mean;
  }
  double direct = kRhoFloor / glm::pi<double>() * kIntensity / (kLightY * kLightY);
  EXPECT_NEAR(m.mean, direct + kRhoFloor * indirect, 5.0 * m.standardError())
      << "direct " << direct << ", indirect " << kRhoFloor * indirect;
}

// The one-step target sees no emission at the ceiling and a ceiling Q that never learns:
// it stays near its initial value, far below what the light gives.
TEST_F(LearningTarget, OneStepTargetCannotLearnAPointLitCeiling) {
  Learned td = learn(guiding::LearningTarget::TdStep, 6);
  const shared::TangentFrame frame = shared::frameFromNormal(glm::vec3(0, 1, 0));
  double pole = reference(0, kRows, kCols, frame).mean;
  EXPECT_LT(td.q[0], 0.1 * pole) << "TD learned " << td.q[0] << ", the light gives " << pole;
}

// What it can learn: with the ceiling glowing at Le, each target of the floor point's pole
// stratum is Le plus what the ceiling's Q says it scatters (>= 0), so their mean is at least
// Le; a renderer that recorded no one-step targets would leave Q at its initial value.
TEST_F(LearningTarget, OneStepTargetLearnsAGlowingCeiling) {
  constexpr float kGlow = 2.0f;
  Learned td = learn(guiding::LearningTarget::TdStep, 6, kGlow);
  EXPECT_GE(td.q[0], 0.99f * kGlow)
      << "TD learned " << td.q[0] << " where the ceiling glows at " << kGlow;
}

}  // namespace
}  // namespace qlight::test
