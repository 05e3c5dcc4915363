#include "engine/guiding/dqn_guide.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "shaders/shared/guiding_types.h"
#include "shaders/shared/specialization.h"

namespace qlight::guiding {
namespace {

constexpr uint32_t kVerticesPerPath = 4;        // records a frame keeps per path, at most
constexpr uint32_t kMaxRingRecords = 1u << 20;  // 32 MB of records
constexpr float kBeta1 = 0.9f, kBeta2 = 0.999f, kAdamEpsilon = 1e-8f;

shared::DqnShape shapeOf(const GuidingSettings& s) {
  return {s.dqnBins, s.dqnWidth, s.dqnHidden, s.strata()};
}

uint32_t frameQuota(uint64_t pathsPerFrame, uint32_t replayFrames) {
  return uint32_t(
      std::clamp<uint64_t>(pathsPerFrame * kVerticesPerPath, 1024, kMaxRingRecords / replayFrames));
}

// The bake pass is specialized on the network's shape and the grid, as the path passes are.
std::vector<uint32_t> bakeSpecialization(shared::DqnShape s, uint32_t grid) {
  std::vector<uint32_t> v(shared::kSpecPathFeatureCount, 0);
  v[shared::kSpecUseDqn] = 1;
  v[shared::kSpecDqnBins] = s.bins;
  v[shared::kSpecDqnWidth] = s.width;
  v[shared::kSpecDqnHidden] = s.hidden;
  v[shared::kSpecDqnOutputs] = s.outputs;
  v[shared::kSpecDqnGrid] = std::max(grid, 1u);
  return v;
}

}  // namespace

DqnGuide::DqnGuide(const gpu::Context& ctx, const GuidingSettings& settings,
                   const render::GpuScene& scene, uint64_t pathsPerFrame)
    : ctx_(ctx),
      settings_((validate(settings), settings)),
      shape_(shapeOf(settings)),
      parameters_(shared::dqnParameterCount(shape_)),
      capacity_(frameQuota(pathsPerFrame, settings.dqnReplayFrames) * settings.dqnReplayFrames),
      quota_(frameQuota(pathsPerFrame, settings.dqnReplayFrames)),
      backprop_(ctx, "dqn_backprop"),
      adam_(ctx, "dqn_adam"),
      evaluate_(ctx, "dqn_evaluate"),
      bake_(ctx, "dqn_bake", bakeSpecialization(shape_, settings.dqnGrid)),
      guidingUniforms_(ctx, sizeof(shared::GuidingUniforms), "dqn.guiding", 0,
                       gpu::MemoryUse::HostVisible),
      online_(ctx, parameters_ * 4ull, "dqn.online"),
      target_(ctx, parameters_ * 4ull, "dqn.target", gpu::kTexelTableUsage),
      moments_(ctx, parameters_ * 8ull, "dqn.adam"),
      gradient_(ctx, parameters_ * 4ull, "dqn.gradient"),
      scratch_(ctx, uint64_t(settings.dqnBatch) * shared::dqnScratchStride(shape_) * 4ull,
               "dqn.scratch"),
      losses_(ctx, settings.dqnBatch * 4ull, "dqn.losses"),
      records_(ctx, uint64_t(capacity_) * sizeof(shared::DqnRecord), "dqn.records"),
      counter_(ctx, 16, "dqn.counter"),
      placeholders_(ctx) {
  // The network covers the scene's bounds at t = 0 (positions outside clamp to its edge).
  const scene::Bounds& b = scene.bounds();
  glm::vec3 lo = b.empty() ? glm::vec3(-1.0f) : b.min, hi = b.empty() ? glm::vec3(1.0f) : b.max;
  const glm::vec3 pad = glm::max(glm::vec3(1e-3f), 0.01f * (hi - lo));
  sceneMin_ = lo - pad;
  sceneInvExtent_ = 1.0f / (hi - lo + 2.0f * pad);
  targetView_ = std::make_unique<gpu::BufferView>(ctx, target_, VK_FORMAT_R32G32B32A32_SFLOAT);
  if (settings.dqnGrid > 0) {
    const uint64_t rows = shared::dqnGridRows(settings.dqnGrid);
    gridRows_ = std::make_unique<gpu::Buffer>(ctx, rows * shape_.outputs * 4ull, "dqn.grid",
                                              gpu::kTexelTableUsage);
    gridView_ = std::make_unique<gpu::BufferView>(ctx, *gridRows_, VK_FORMAT_R32_SFLOAT);
  }
  uploadWeights(initialWeights(shape_, settings.seed));
  std::vector<shared::DqnRecord> none(capacity_,
                                      shared::DqnRecord{{}, 0, {}, shared::kDqnNoTarget});
  records_.upload<shared::DqnRecord>(ctx, none);
  counter_.upload<uint32_t>(ctx, std::vector<uint32_t>(4, 0));
  upload();
  if (settings.target == LearningTarget::TdStep)
    std::fprintf(stderr,
                 "qlight: warning: the deep Q network learns from returns; the TD target "
                 "(--learning-target td) applies to the Q tables only\n");
}

std::vector<float> DqnGuide::initialWeights(shared::DqnShape s, uint32_t seed) {
  std::vector<float> w(shared::dqnParameterCount(s), 0.0f);
  std::mt19937 rng(seed * 7919u + 17u);
  for (uint32_t l = 0; l < shared::dqnLayerCount(s); ++l) {
    const uint32_t ins = shared::dqnLayerInputs(s, l), outs = shared::dqnLayerOutputs(s, l);
    const uint32_t stride = shared::dqnRowStride(s, l), base = shared::dqnWeightOffset(s, l);
    // He initialisation for the ReLU layers; the output layer starts 10x smaller, so every
    // stratum's Q starts near exp(0) = 1 and the first guided samples are near cosine.
    const float sigma = std::sqrt(2.0f / float(ins)) * (l == s.hidden ? 0.1f : 1.0f);
    std::normal_distribution<float> normal(0.0f, sigma);
    for (uint32_t o = 0; o < outs; ++o)
      for (uint32_t i = 0; i < ins; ++i) w[base + o * stride + i] = normal(rng);
  }
  return w;
}

void DqnGuide::uploadWeights(const std::vector<float>& weights) {
  if (weights.size() != parameters_) throw std::invalid_argument("network parameters mismatch");
  online_.upload<float>(ctx_, weights);
  target_.upload<float>(ctx_, weights);
  moments_.upload<float>(ctx_, std::vector<float>(2 * size_t(parameters_), 0.0f));
  gradient_.upload<float>(ctx_, std::vector<float>(parameters_, 0.0f));
  steps_ = 0;
  if (gridRows_)
    ctx_.submitAndWait([&](VkCommandBuffer cmd) {
      gpu::PassRecorder rec(ctx_, cmd);
      recordBake(rec);
      rec.finish();
    });
}

glm::vec3 DqnGuide::position01(glm::vec3 world) const {
  return (world - sceneMin_) * sceneInvExtent_;
}

bool DqnGuide::sameShape(const GuidingSettings& s) const {
  const shared::DqnShape n = shapeOf(s);
  return n.bins == shape_.bins && n.width == shape_.width && n.hidden == shape_.hidden &&
         n.outputs == shape_.outputs && s.dqnBatch == settings_.dqnBatch &&
         s.dqnReplayFrames == settings_.dqnReplayFrames && s.dqnGrid == settings_.dqnGrid &&
         (s.dqnGrid == 0 || (s.dqnFloorShare == settings_.dqnFloorShare &&
                             s.rows == settings_.rows && s.cols == settings_.cols));
}

render::GuideFeatures DqnGuide::features() const {
  render::GuideFeatures f;
  f.points = true;  // the guiding code paths, with the network for the points
  f.dqn = true;
  f.dqnBins = shape_.bins;
  f.dqnWidth = shape_.width;
  f.dqnHidden = shape_.hidden;
  f.dqnOutputs = shape_.outputs;
  f.dqnGrid = settings_.dqnGrid;
  f.learns = settings_.learn;
  return f;
}

void DqnGuide::upload() {
  // The guiding block: sample by the network, learn from returns; no points, no V.
  shared::GuidingUniforms g{};
  g.rows = settings_.rows;
  g.cols = settings_.cols;
  g.hashSize = 1;
  g.flags = shared::kGuideSample | shared::kGuideDqn | shared::kGuideLearnReturns;
  if (settings_.learn) g.flags |= shared::kGuideLearn;
  if (settings_.guidedRoulette) g.flags |= shared::kGuideRoulette;
  g.selectProbability = settings_.selectProbability;
  g.qFloor = settings_.qFloor;
  g.alphaMin = settings_.alphaMin;
  g.alphaMax = settings_.alphaMax;
  shared::DqnUniforms& u = g.dqn;
  u.shape = shape_;
  u.sceneMin = sceneMin_;
  u.sceneInvExtent = sceneInvExtent_;
  u.capacity = capacity_;
  u.frameStart = frameStart_;
  u.frameQuota = settings_.learn ? quota_ : 0;
  u.confidence = stats().confidence;
  u.floorShare = settings_.dqnFloorShare;
  u.targetScale = 1.0f;
  guidingUniforms_.upload(ctx_, &g, sizeof(g));
}

void DqnGuide::bind(gpu::PassBuilder& pass) const {
  // The tables' slots carry the network, the replay ring and its count (guide_bindings.h).
  GuideBuffers b = placeholders_.buffers();
  b.uniforms = &guidingUniforms_;
  b.qCdf = gridView_ ? gridView_.get() : targetView_.get();
  b.qSums = &records_;
  b.qCounts = &counter_;
  bindGuideBuffers(pass, b);
}

void DqnGuide::recordStep(gpu::PassRecorder& rec, bool apply) {
  ++steps_;
  shared::DqnTrainPush push{};
  push.shape = shape_;
  push.batch = settings_.dqnBatch;
  push.capacity = capacity_;
  push.step = steps_;
  push.targetScale = 1.0f;
  push.learningRate = apply ? settings_.dqnLearningRate : 0.0f;
  push.beta1 = kBeta1;
  push.beta2 = kBeta2;
  push.epsilon = kAdamEpsilon;
  rec.pass("dqn.backprop", backprop_)
      .read(QL_DQN_BIND_WEIGHTS, online_)
      .read(QL_DQN_BIND_RECORDS, records_)
      .write(QL_DQN_BIND_SCRATCH, scratch_)
      .write(QL_DQN_BIND_LOSS, losses_)
      .push(push)
      .dispatchThreads(push.batch);
  rec.pass("dqn.adam", adam_)
      .write(QL_DQN_BIND_WEIGHTS, online_)
      .read(QL_DQN_BIND_SCRATCH, scratch_)
      .write(QL_DQN_BIND_ADAM, moments_)
      .write(QL_DQN_BIND_GRADIENT, gradient_)
      .push(push)
      .dispatchThreads(parameters_);
}

void DqnGuide::recordLearning(gpu::PassRecorder& rec) {
  ++frames_;
  if (settings_.learn)
    for (uint32_t s = 0; s < settings_.dqnStepsPerFrame; ++s) recordStep(rec);
  rec.fill("dqn.counter_reset", counter_, 0);
  frameStart_ = (frameStart_ + quota_) % capacity_;
  if (settings_.learn && frames_ % settings_.dqnTargetInterval == 0) {
    rec.copy("dqn.target_copy", online_, target_, parameters_ * 4ull);
    if (gridRows_) recordBake(rec);
  }
}

void DqnGuide::recordBake(gpu::PassRecorder& rec) {
  shared::DqnBakePush push{};
  push.rows = settings_.rows;
  push.cols = settings_.cols;
  push.floorShare = settings_.dqnFloorShare;
  rec.pass("dqn.bake", bake_)
      .read(QL_DQN_BIND_WEIGHTS, *targetView_)
      .write(QL_DQN_BIND_OUTPUT, *gridRows_)
      .push(push)
      .dispatchThreads(shared::dqnGridRows(settings_.dqnGrid));
}

std::vector<float> DqnGuide::readGridRows() const {
  return gridRows_ ? gridRows_->read<float>(ctx_) : std::vector<float>{};
}

std::vector<float> DqnGuide::readWeights() const { return online_.read<float>(ctx_); }
std::vector<float> DqnGuide::readTargetWeights() const { return target_.read<float>(ctx_); }
std::vector<float> DqnGuide::readGradient() const { return gradient_.read<float>(ctx_); }
std::vector<float> DqnGuide::readLosses() const { return losses_.read<float>(ctx_); }
std::vector<shared::DqnRecord> DqnGuide::readRecords() const {
  return records_.read<shared::DqnRecord>(ctx_);
}

void DqnGuide::uploadRecords(const std::vector<shared::DqnRecord>& records) {
  if (records.size() != capacity_) throw std::invalid_argument("replay ring size mismatch");
  records_.upload<shared::DqnRecord>(ctx_, records);
}

void DqnGuide::trainNow(bool apply) {
  ctx_.submitAndWait([&](VkCommandBuffer cmd) {
    gpu::PassRecorder rec(ctx_, cmd);
    recordStep(rec, apply);
    rec.finish();
  });
}

std::vector<float> DqnGuide::evaluate(const std::vector<shared::DqnRecord>& states) const {
  if (states.empty()) return {};
  gpu::Buffer in(ctx_, states.size() * sizeof(shared::DqnRecord), "dqn.states");
  gpu::Buffer out(ctx_, states.size() * shape_.outputs * 4ull, "dqn.q");
  in.upload<shared::DqnRecord>(ctx_, states);
  shared::DqnTrainPush push{};
  push.shape = shape_;
  push.batch = uint32_t(states.size());
  ctx_.submitAndWait([&](VkCommandBuffer cmd) {
    gpu::PassRecorder rec(ctx_, cmd);
    rec.pass("dqn.evaluate", evaluate_)
        .read(QL_DQN_BIND_WEIGHTS, online_)
        .read(QL_DQN_BIND_RECORDS, in)
        .write(QL_DQN_BIND_OUTPUT, out)
        .push(push)
        .dispatchThreads(push.batch);
    rec.finish();
  });
  return out.read<float>(ctx_);
}

DqnStats DqnGuide::stats() const {
  DqnStats s;
  s.parameters = parameters_;
  s.steps = steps_;
  s.recordsPerFrame = quota_;
  s.capacity = capacity_;
  const uint32_t warmup = settings_.dqnWarmupSteps;
  s.confidence = warmup == 0 ? 1.0f : std::min(1.0f, float(steps_) / float(warmup));
  return s;
}

uint64_t DqnGuide::memoryBytes() const {
  return online_.size() + target_.size() + moments_.size() + gradient_.size() + scratch_.size() +
         losses_.size() + records_.size() + counter_.size() + guidingUniforms_.size() +
         (gridRows_ ? gridRows_->size() : 0);
}

}  // namespace qlight::guiding
