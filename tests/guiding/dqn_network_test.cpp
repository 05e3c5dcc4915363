// The deep Q network (shaders/shared/dqn.h, engine/guiding/dqn_guide.h) against a CPU
// reference written here from the layout alone: its forward pass, the gradient of its
// training step (checked by finite differences), and that training on the GPU learns a
// known function of the state.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "engine/guiding/dqn_guide.h"
#include "engine/scene/scene_asset.h"
#include "shaders/shared/strata.h"
#include "tests/gpu/gpu_fixture.h"
#include "tests/render/furnace_scene.h"

namespace qlight::test {
namespace {

using shared::DqnRecord;
using shared::DqnShape;

// The reference: plain loops over the layout's offsets.
struct CpuNetwork {
  DqnShape s;
  std::vector<double> w;

  double weight(uint32_t layer, uint32_t out, uint32_t in) const {
    return w[shared::dqnWeightOffset(s, layer) + out * shared::dqnRowStride(s, layer) + in];
  }
  double bias(uint32_t layer, uint32_t out) const {
    return w[shared::dqnBiasOffset(s, layer) + out];
  }
  std::vector<double> inputs(const DqnRecord& r) const {
    std::vector<double> x;
    const float p[3] = {r.position01.x, r.position01.y, r.position01.z};
    for (int axis = 0; axis < 3; ++axis)
      for (uint32_t b = 0; b < s.bins; ++b) {
        const double c = (b + 0.5) / s.bins,
                     d = (std::clamp(double(p[axis]), 0.0, 1.0) - c) * s.bins;
        x.push_back(std::exp(-0.5 * d * d));
      }
    x.push_back(r.normal.x);
    x.push_back(r.normal.y);
    x.push_back(r.normal.z);
    return x;
  }
  // z per output.
  std::vector<double> forward(const DqnRecord& r) const {
    std::vector<double> a = inputs(r);
    for (uint32_t l = 0; l <= s.hidden; ++l) {
      std::vector<double> next(shared::dqnLayerOutputs(s, l));
      for (uint32_t o = 0; o < next.size(); ++o) {
        double z = bias(l, o);
        for (uint32_t i = 0; i < a.size(); ++i) z += weight(l, o, i) * a[i];
        next[o] = l == s.hidden ? z : std::max(z, 0.0);
      }
      a = std::move(next);
    }
    return a;
  }
};

class DqnNetwork : public GpuTest {
 protected:
  // A guide on a small scene; the network's shape from `g`.
  std::unique_ptr<guiding::DqnGuide> makeGuide(const guiding::GuidingSettings& g) {
    asset_ = whiteFurnace(0.5f, 1.0f);
    scene_ = std::make_unique<render::GpuScene>(ctx(), asset_);
    return std::make_unique<guiding::DqnGuide>(ctx(), g, *scene_, 256);
  }
  // Normal weights of deviation `sigma` into both copies (larger than the initial ones, so
  // the ReLUs cut and the outputs spread); returns them.
  static std::vector<float> uploadRandomWeights(guiding::DqnGuide& guide, std::mt19937& rng,
                                                float sigma) {
    std::normal_distribution<float> normal(0.0f, sigma);
    std::vector<float> w(guide.stats().parameters);
    for (float& x : w) x = normal(rng);
    guide.uploadWeights(w);
    return w;
  }
  static DqnRecord randomRecord(std::mt19937& rng, uint32_t strata) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    DqnRecord r{};
    r.position01 = {u(rng), u(rng), u(rng)};
    glm::vec3 n(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f);
    r.normal = glm::normalize(n + glm::vec3(1e-3f));
    r.stratum = rng() % strata;
    r.target = 0.0f;
    return r;
  }
  scene::SceneAsset asset_;
  std::unique_ptr<render::GpuScene> scene_;
};

guiding::GuidingSettings dqnSettings() {
  guiding::GuidingSettings g;
  g.method = guiding::GuideMethod::Dqn;
  g.rows = g.cols = 4;
  g.dqnWidth = 16;
  g.dqnHidden = 2;
  g.dqnBins = 8;
  g.dqnBatch = 512;
  return g;
}

TEST_F(DqnNetwork, ForwardPassMatchesTheCpuReference) {
  auto guide = makeGuide(dqnSettings());
  // Weights larger than the initial ones, so the ReLUs cut and the outputs spread.
  std::mt19937 rng(5);
  const std::vector<float> w = uploadRandomWeights(*guide, rng, 0.4f);
  CpuNetwork ref{guide->shape(), std::vector<double>(w.begin(), w.end())};
  std::vector<DqnRecord> states;
  for (int i = 0; i < 200; ++i) states.push_back(randomRecord(rng, 16));
  states.push_back({{-0.5f, 1.5f, 0.5f}, 0, {0.0f, 0.0f, 1.0f}, 0.0f});  // clamps to the edge
  const std::vector<float> q = guide->evaluate(states);
  ASSERT_EQ(q.size(), states.size() * 16);
  double spread = 0;
  for (size_t i = 0; i < states.size(); ++i) {
    const std::vector<double> z = ref.forward(states[i]);
    for (uint32_t k = 0; k < 16; ++k) {
      const double expected = std::exp(z[k]);
      EXPECT_NEAR(q[i * 16 + k], expected, 1e-4 * expected + 1e-6) << "state " << i << " k " << k;
      spread = std::max(spread, std::abs(z[k]));
    }
  }
  EXPECT_GT(spread, 1.0) << "outputs must not all be near exp(0)";
}

// The baked grid (--dqn-grid): every row is the sampling CDF of the network at its cell's
// centre and its axis normal, (Q_k + floor share x mean Q) times the stratum's cosine
// integral, accumulated, from the CPU reference; and a state reads the row of the cell it
// lies in and of the axis nearest its normal.
TEST_F(DqnNetwork, BakedGridRowsAreTheNetworksCdfAtTheCellCentres) {
  guiding::GuidingSettings g = dqnSettings();
  g.dqnGrid = 3;
  auto guide = makeGuide(g);
  std::mt19937 rng(7);
  const std::vector<float> w = uploadRandomWeights(*guide, rng, 0.4f);  // bakes the grid
  CpuNetwork ref{guide->shape(), std::vector<double>(w.begin(), w.end())};
  const uint32_t strata = 16, rows = shared::dqnGridRows(3);
  const std::vector<float> cdf = guide->readGridRows();
  ASSERT_EQ(cdf.size(), size_t(rows) * strata);
  for (uint32_t row = 0; row < rows; ++row) {
    const DqnRecord state{shared::dqnGridRowPosition01(row, 3), 0,
                          shared::dqnGridNormal(row % shared::kDqnGridNormals), 0.0f};
    const std::vector<double> z = ref.forward(state);
    double mean = 0;
    for (double x : z) mean += std::exp(x) / strata;
    double run = 0;
    for (uint32_t k = 0; k < strata; ++k) {
      run += (std::exp(z[k]) + g.dqnFloorShare * mean) * shared::stratumCosineIntegral(k, 4, 4);
      ASSERT_NEAR(cdf[row * strata + k], run, 1e-4 * run) << "row " << row << " stratum " << k;
    }
  }
  // Which row a state reads: its cell (3 per axis) and its normal's nearest axis.
  EXPECT_EQ(shared::dqnGridRow({0.1f, 0.5f, 0.9f}, glm::vec3(0.2f, -0.9f, 0.1f), 3),
            (0u + 3u * (1u + 3u * 2u)) * 6u + 3u);  // cell (0, 1, 2), -y
  EXPECT_EQ(shared::dqnGridRow({1.2f, -0.1f, 0.34f}, glm::vec3(0.0f, 0.3f, 0.95f), 3),
            (2u + 3u * (0u + 3u * 1u)) * 6u + 4u);  // clamped to the edges, cell (2, 0, 1), +z
  for (int i = 0; i < 100; ++i) {
    const DqnRecord r = randomRecord(rng, strata);
    const uint32_t row = shared::dqnGridRow(r.position01, r.normal, 3);
    const glm::vec3 centre = shared::dqnGridRowPosition01(row, 3);
    EXPECT_LE(glm::length(glm::max(glm::abs(centre - r.position01) - 0.5f / 3, 0.0f)), 1e-6f);
    const glm::vec3 axis = shared::dqnGridNormal(row % 6);
    for (uint32_t b = 0; b < 6; ++b)
      EXPECT_GE(glm::dot(axis, r.normal), glm::dot(shared::dqnGridNormal(b), r.normal));
  }
}

// The training step's gradient (dqn_backprop + dqn_adam with no step) against finite
// differences of the batch's loss on the CPU reference, the relative-L2 denominator held
// at the current Q as the stop-gradient says.
TEST_F(DqnNetwork, BackwardPassMatchesFiniteDifferences) {
  guiding::GuidingSettings g = dqnSettings();
  g.dqnBatch = 64;
  auto guide = makeGuide(g);
  std::mt19937 rng(9);
  const std::vector<float> w = uploadRandomWeights(*guide, rng, 0.3f);
  const DqnShape s = guide->shape();
  CpuNetwork ref{s, std::vector<double>(w.begin(), w.end())};
  std::vector<DqnRecord> ring(guide->capacity());
  for (DqnRecord& r : ring) {
    r = randomRecord(rng, s.outputs);
    // Targets near the current Q (no gradient clamp), a fifth without a return.
    const double q = std::exp(ref.forward(r)[r.stratum]);
    r.target = rng() % 5 == 0 ? shared::kDqnNoTarget : float(q * (0.5 + (rng() % 100) / 100.0));
  }
  guide->uploadRecords(ring);
  guide->trainNow(false);  // step 1: the gradient only
  const std::vector<float> gpu = guide->readGradient();
  ASSERT_EQ(guide->readWeights(), w) << "no step was to be taken";

  std::vector<DqnRecord> batch;
  for (uint32_t b = 0; b < g.dqnBatch; ++b)
    batch.push_back(ring[shared::dqnDrawnRecord(1, b, guide->capacity())]);
  std::vector<double> q0;
  for (const DqnRecord& r : batch) q0.push_back(std::exp(ref.forward(r)[r.stratum]));
  auto loss = [&](const CpuNetwork& net) {
    double sum = 0;
    for (size_t b = 0; b < batch.size(); ++b) {
      if (!(batch[b].target >= 0)) continue;
      const double q = std::exp(net.forward(batch[b])[batch[b].stratum]), y = batch[b].target;
      const double e = shared::kDqnLossEpsilon;
      sum += (q - y) * (q - y) / (q0[b] * q0[b] + e * e);
    }
    return sum / double(batch.size());
  };
  // Every layer's weights and biases, some of each.
  int checked = 0;
  for (uint32_t l = 0; l <= s.hidden; ++l) {
    const uint32_t ins = shared::dqnLayerInputs(s, l), outs = shared::dqnLayerOutputs(s, l);
    for (int t = 0; t < 12; ++t) {
      const bool bias = t % 4 == 0;
      const uint32_t o = rng() % outs, i = rng() % ins;
      const uint32_t p = bias ? shared::dqnBiasOffset(s, l) + o
                              : shared::dqnWeightOffset(s, l) + o * shared::dqnRowStride(s, l) + i;
      const double h = 1e-4;
      CpuNetwork up = ref, down = ref;
      up.w[p] += h;
      down.w[p] -= h;
      const double numeric = (loss(up) - loss(down)) / (2 * h);
      EXPECT_NEAR(gpu[p], numeric, 2e-3 * std::abs(numeric) + 1e-5)
          << "layer " << l << (bias ? " bias " : " weight ") << o << "," << i;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 36);
  // Padding parameters have no gradient.
  if (shared::dqnRowStride(s, 0) > shared::dqnLayerInputs(s, 0)) {
    EXPECT_EQ(gpu[shared::dqnLayerInputs(s, 0)], 0.0f);
  }
}

// A synthetic incident radiance: the light is seen through one stratum, which one depends on
// which quarter of the scene's x the position is in, 9x brighter than the rest.
// Trained on noisy returns of it (mean Q*, exponential noise) for 600 steps, the network
// reproduces it at states it has not seen within 35% per stratum on average (measured 26%:
// the error is largest where the quarters meet; untrained, Q ~ 1 is off by ~900%), and the
// lit stratum gets its share of the sum (0.375) within 0.05 (measured 0.362).
TEST_F(DqnNetwork, LearnsAKnownIncidentRadiance) {
  guiding::GuidingSettings g = dqnSettings();
  g.dqnWidth = 32;
  g.dqnBins = 16;
  g.dqnBatch = 1024;
  g.dqnLearningRate = 3e-3f;
  auto guide = makeGuide(g);
  const uint32_t strata = 16;
  auto truth = [&](const DqnRecord& r, uint32_t k) {
    const uint32_t quarter = std::min(3u, uint32_t(r.position01.x * 4.0f));
    return k == 5 * quarter ? 0.9 : 0.1;
  };
  std::mt19937 rng(21);
  std::exponential_distribution<double> noise(1.0);
  std::vector<DqnRecord> ring(guide->capacity());
  for (DqnRecord& r : ring) {
    r = randomRecord(rng, strata);
    r.normal = {0.0f, 0.0f, 1.0f};
    r.target = float(truth(r, r.stratum) * noise(rng));
  }
  guide->uploadRecords(ring);
  for (int step = 0; step < 600; ++step) guide->trainNow(true);
  std::vector<DqnRecord> states;
  for (int i = 0; i < 100; ++i) {
    DqnRecord r = randomRecord(rng, strata);
    r.normal = {0.0f, 0.0f, 1.0f};
    states.push_back(r);
  }
  const std::vector<float> q = guide->evaluate(states);
  double error = 0, litShare = 0;
  for (size_t i = 0; i < states.size(); ++i) {
    double sum = 0, lit = 0;
    for (uint32_t k = 0; k < strata; ++k) {
      const double t = truth(states[i], k);
      error += std::abs(q[i * strata + k] - t) / t;
      sum += q[i * strata + k];
      if (t > 0.5) lit = q[i * strata + k];
    }
    litShare += lit / sum;
  }
  error /= double(states.size() * strata);
  litShare /= double(states.size());
  EXPECT_LT(error, 0.35) << "mean relative error of Q";
  // The truth gives the lit stratum 0.9 / 2.4 = 0.375 of the sum; untrained, 1/16.
  EXPECT_NEAR(litShare, 0.375, 0.05);
  std::printf("learned: mean relative error %.3f, lit stratum's share %.3f (truth 0.375)\n", error,
              litShare);
}

}  // namespace
}  // namespace qlight::test
