#include "engine/guiding/q_guiding.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "engine/guiding/cache_point.h"
#include "engine/guiding/point_acceptance.h"

namespace qlight::guiding {
namespace {

constexpr uint32_t kSpawnCapacity = 4096;
constexpr uint64_t kMaxLightEntries = 4u << 20;  // points x lights for light learning
constexpr uint32_t kLightUpdateInterval = 4;

uint32_t nextPowerOfTwo(uint32_t v) {
  uint32_t p = 1;
  while (p < v) p <<= 1;
  return p;
}

uint32_t floatBits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, 4);
  return u;
}

using BufferPtr = std::unique_ptr<gpu::Buffer>;

constexpr VkBufferUsageFlags kTexel = VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT;

BufferPtr makeBuffer(const gpu::Context& ctx, uint64_t bytes, const std::string& name,
                     gpu::MemoryUse use = gpu::MemoryUse::DeviceLocal, VkBufferUsageFlags usage = kTexel) {
  return std::make_unique<gpu::Buffer>(ctx, std::max<uint64_t>(bytes, 16), name, usage, use);
}

using ViewPtr = std::unique_ptr<gpu::BufferView>;

// One learned table (Q over strata, or V over lights) and its frame accumulators.
struct Table {
  BufferPtr values, visits, cdf, sums, counts;
  ViewPtr cdfView;  // the path passes read the CDF as a texel buffer
  void allocate(const gpu::Context& ctx, uint64_t entries, const std::string& name) {
    cdfView.reset();
    values = makeBuffer(ctx, entries * 4, name + ".values");
    visits = makeBuffer(ctx, entries * 4, name + ".visits");
    cdf = makeBuffer(ctx, entries * 4, name + ".cdf");
    sums = makeBuffer(ctx, entries * 8, name + ".sums");  // 64-bit fixed point per entry
    counts = makeBuffer(ctx, entries * 4, name + ".counts");
    cdfView = std::make_unique<gpu::BufferView>(ctx, *cdf, VK_FORMAT_R32_SFLOAT);
  }
  void recordReset(gpu::PassRecorder& rec, float initial) const {
    rec.fill("guiding.reset", *values, floatBits(initial));
    rec.fill("guiding.reset", *visits, 0);
    rec.fill("guiding.reset", *sums, 0);
    rec.fill("guiding.reset", *counts, 0);
    rec.fill("guiding.reset", *cdf, 0);
  }
};

}  // namespace

struct QGuiding::Tables {
  BufferPtr uniforms, points, gridBuckets, gridPoints, spawn, candidates, pointUpdates;
  ViewPtr pointsView, gridBucketsView, gridPointsView;
  Table q, v;
  std::unique_ptr<PointAcceptor> acceptor;
  uint32_t candidateCapacity = 0;
};

QGuiding::QGuiding(const gpu::Context& ctx, const GuidingSettings& settings)
    : ctx_(ctx), settings_(settings), scan_(ctx), update_(ctx, "q_update"),
      darts_(ctx, "guiding_darts"), t_(std::make_unique<Tables>()) {
  validate(settings_);
  allocate(0);
}

QGuiding::~QGuiding() = default;

void QGuiding::setSettings(const GuidingSettings& s) {
  validate(s);
  GuidingSettings old = settings_;
  settings_ = s;
  bool pointsChanged = s.pointBudget != old.pointBudget || s.rejectionMin != old.rejectionMin ||
                       s.rejectionMax != old.rejectionMax || s.pointSet != old.pointSet ||
                       s.normalCosine != old.normalCosine || s.dartPaths != old.dartPaths ||
                       s.dartBounces != old.dartBounces || s.seed != old.seed ||
                       s.lightLearning != old.lightLearning;
  bool tablesChanged = s.rows != old.rows || s.cols != old.cols || s.initialQ != old.initialQ ||
                       s.qFloor != old.qFloor;
  if (pointsChanged) {
    needsPoints_ = true;
  } else if (tablesChanged) {
    allocateTables(lightCount_);
    resetTables();
  }
  writeUniforms();
}

// The learned tables alone: a strata change keeps the points and their grid.
void QGuiding::allocateTables(uint32_t lightCount) {
  const uint64_t budget = settings_.pointBudget;
  t_->q.allocate(ctx_, budget * settings_.strata(), "guiding.q");
  lightCount_ = lightCount;
  t_->v.allocate(ctx_, std::max<uint64_t>(budget * lightCount, 1), "guiding.v");
}

void QGuiding::allocate(uint32_t lightCount) {
  const uint64_t budget = settings_.pointBudget;
  grid_.hashSize = nextPowerOfTwo(std::max<uint32_t>(2 * settings_.pointBudget, 1024));
  t_->pointsView.reset();
  t_->gridBucketsView.reset();
  t_->gridPointsView.reset();
  t_->uniforms = makeBuffer(ctx_, sizeof(shared::GuidingUniforms), "guiding.uniforms",
                            gpu::MemoryUse::HostVisible, 0);
  t_->points = makeBuffer(ctx_, budget * sizeof(CachePoint), "guiding.points");
  t_->gridBuckets = makeBuffer(ctx_, (grid_.hashSize + 1ull) * 4, "guiding.gridBuckets");
  t_->gridPoints = makeBuffer(ctx_, budget * 4, "guiding.gridPoints");
  t_->pointUpdates = makeBuffer(ctx_, budget * 4, "guiding.pointUpdates");
  t_->pointsView = std::make_unique<gpu::BufferView>(ctx_, *t_->points, VK_FORMAT_R32G32B32A32_SFLOAT);
  t_->gridBucketsView = std::make_unique<gpu::BufferView>(ctx_, *t_->gridBuckets, VK_FORMAT_R32_UINT);
  t_->gridPointsView = std::make_unique<gpu::BufferView>(ctx_, *t_->gridPoints, VK_FORMAT_R32_UINT);
  t_->spawn = makeBuffer(ctx_, kSpawnCapacity * 32ull, "guiding.spawn");
  t_->candidateCapacity = settings_.dartPaths * settings_.dartBounces;
  t_->candidates = makeBuffer(ctx_, t_->candidateCapacity * 32ull, "guiding.candidates");
  allocateTables(lightCount);
  pointCount_ = 0;  // the point buffers are new: generatePoints fills them
  grid_.buckets.assign(grid_.hashSize + 1, 0);
  t_->gridBuckets->upload(ctx_, grid_.buckets.data(), grid_.buckets.size() * 4);
  std::vector<uint8_t> zeros(kSpawnCapacity * 32ull, 0);
  t_->spawn->upload(ctx_, zeros.data(), zeros.size());
}

void QGuiding::resetTables() {
  // Fresh tables: uniform Q (cosine sampling), no visits; the update pass with
  // no targets then writes the CDF weights, and the scan the CDFs, for every
  // slot of the budget, so points added later start with a valid distribution.
  ctx_.submitAndWait([&](VkCommandBuffer cmd) {
    gpu::PassRecorder rec(ctx_, cmd);
    t_->q.recordReset(rec, settings_.initialQ);
    rec.fill("guiding.reset", *t_->pointUpdates, 0);
    // Light values start at the floor: until a light has shown a contribution at
    // a point, NEE picks it by power (the mixture), not uniformly among all lights.
    t_->v.recordReset(rec, settings_.qFloor);
    recordTables(rec, settings_.pointBudget);
    rec.finish();
  });
}

void QGuiding::chooseRadii(const render::GpuScene& scene) {
  // Random sequential adsorption saturates at about 0.7 A / r^2 points on
  // area A: aim the darts at half the budget, leaving room for camera spawns.
  float area = std::max(scene.surfaceArea(), 1e-6f);
  float autoMin = std::sqrt(0.7f * area / (0.5f * float(settings_.pointBudget)));
  rejectionMin_ = settings_.rejectionMin > 0 ? settings_.rejectionMin : autoMin;
  rejectionMax_ = settings_.pointSet == PointSet::PhotonMap ? rejectionMin_
                  : settings_.rejectionMax > 0 ? settings_.rejectionMax
                                               : 3.0f * rejectionMin_;
  // Saturated darts leave no surface point much farther than the rejection
  // distance from a point; gaps are filled by camera spawns. A larger radius
  // covers the same but visits more points per search (9% of the shade pass
  // at 1.25x on lavapipe).
  searchRadius_ = rejectionMax_;
  grid_.cellSize = 2.0f * searchRadius_;
}

void QGuiding::generatePoints(ecs::Registry& registry, const render::GpuScene& scene) {
  std::vector<ecs::Entity> old;
  registry.view<const CachePoint>().each([&](ecs::Entity e, const CachePoint&) { old.push_back(e); });
  for (ecs::Entity e : old) registry.destroy(e);
  sceneLights_ = scene.lightCount();
  uint32_t lights = 0;
  if (settings_.lightLearning && sceneLights_ > 1 &&
      sceneLights_ <= gpu::PrefixSum::kMaxSegmentLength &&
      uint64_t(sceneLights_) * settings_.pointBudget <= kMaxLightEntries)
    lights = sceneLights_;
  else if (settings_.lightLearning && sceneLights_ > 1)
    std::fprintf(stderr, "qlight: light-selection learning off: %u lights x %u points exceeds its table\n",
                 sceneLights_, settings_.pointBudget);
  pointCount_ = 0;
  spawned_ = 0;
  allocate(lights);
  chooseRadii(scene);

  // Darts from the lights; the GPU traces, the CPU accepts by rejection distance.
  std::vector<glm::vec4> raw;
  if (scene.lightCount() > 0) {
    shared::DartsPush push{};
    push.pathCount = settings_.dartPaths;
    push.maxBounces = settings_.dartBounces;
    push.lightCount = scene.lightCount();
    push.seed = settings_.seed + 7919u * ++generation_;
    push.sceneCenter = scene.boundsCenter();
    push.sceneRadius = scene.boundsRadius();
    push.aoRadius = rejectionMax_ * 2.0f;
    push.aoRays = settings_.pointSet == PointSet::PoissonAo ? 8 : 0;
    push.capacity = t_->candidateCapacity;
    ctx_.submitAndWait([&](VkCommandBuffer cmd) {
      gpu::PassRecorder rec(ctx_, cmd);
      rec.fill("guiding.darts.clear", *t_->candidates, 0xffffffffu);  // NaN: slot unused
      auto pass = rec.pass("guiding.darts", darts_);
      scene.bind(pass);
      pass.write(QL_BIND_DART_CANDIDATES, *t_->candidates).push(push).dispatchThreads(push.pathCount);
      rec.finish();
    });
    raw.resize(size_t(t_->candidateCapacity) * 2);
    t_->candidates->download(ctx_, raw.data(), raw.size() * sizeof(glm::vec4));
  }
  t_->acceptor = std::make_unique<PointAcceptor>(rejectionMax_, settings_.normalCosine);
  for (size_t i = 0; 2 * i < raw.size() && pointCount_ < settings_.pointBudget; ++i) {
    if (!std::isfinite(raw[2 * i].x)) continue;  // the dart's path ended before this bounce
    PointCandidate c{glm::vec3(raw[2 * i]), glm::vec3(raw[2 * i + 1]), raw[2 * i].w};
    float radius = settings_.pointSet == PointSet::PhotonMap
                       ? rejectionMin_
                       : rejectionMax_ + (rejectionMin_ - rejectionMax_) * c.occlusion;
    CachePoint accepted;
    if (t_->acceptor->tryAccept(c, radius, accepted)) {
      registry.emplace<CachePoint>(registry.create(), accepted);
      ++pointCount_;
    }
  }
  needsPoints_ = false;
  resetTables();
  uploadPoints(registry);
}

void QGuiding::uploadPoints(ecs::Registry& registry) {
  auto& storage = registry.storage<CachePoint>();
  pointCount_ = uint32_t(std::min<size_t>(storage.size(), settings_.pointBudget));
  std::span<const CachePoint> points(storage.data(), pointCount_);
  // Only the slots that changed go to the GPU (new points append).
  auto dirty = storage.dirtyRange();
  uint32_t begin = std::min<uint32_t>(dirty.begin, pointCount_);
  uint32_t end = std::min<uint32_t>(dirty.end, pointCount_);
  if (end > begin)
    t_->points->upload(ctx_, points.data() + begin, (end - begin) * sizeof(CachePoint),
                       begin * sizeof(CachePoint));
  storage.clearDirty();
  grid_ = buildPointGrid(points, grid_.cellSize, grid_.hashSize);
  t_->gridBuckets->upload(ctx_, grid_.buckets.data(), grid_.buckets.size() * 4);
  if (!grid_.points.empty()) t_->gridPoints->upload(ctx_, grid_.points.data(), grid_.points.size() * 4);
  writeUniforms();
}

void QGuiding::writeUniforms() {
  shared::GuidingUniforms u{};
  u.rows = settings_.rows;
  u.cols = settings_.cols;
  u.pointCount = pointCount_;
  bool on = settings_.enabled && pointCount_ > 0;
  u.flags = 0;
  if (on) u.flags |= shared::kGuideSample;
  if (on && settings_.learn) u.flags |= shared::kGuideLearn;
  if (on && lightCount_ > 0) u.flags |= shared::kGuideLightLearn;
  if (settings_.enabled && settings_.spawnFromCamera && pointCount_ < settings_.pointBudget &&
      t_->acceptor)
    u.flags |= shared::kGuideSpawn;
  u.searchRadius = searchRadius_;
  u.cellSize = grid_.cellSize;
  u.hashSize = grid_.hashSize;
  u.selectProbability = settings_.selectProbability;
  u.normalCosine = settings_.normalCosine;
  u.qFloor = settings_.qFloor;
  u.lightMix = settings_.lightMix;
  u.lightCount = lightCount_;
  u.spawnCapacity = kSpawnCapacity;
  u.alphaMin = settings_.alphaMin;
  u.alphaMax = settings_.alphaMax;
  u.confidenceUpdates = settings_.confidenceUpdates;
  t_->uniforms->upload(ctx_, &u, sizeof(u));
}

void QGuiding::bind(gpu::PassBuilder& pass) const {
  pass.read(QL_BIND_GUIDING, *t_->uniforms)
      .read(QL_BIND_CACHE_POINTS, *t_->pointsView)
      .read(QL_BIND_GRID_BUCKETS, *t_->gridBucketsView)
      .read(QL_BIND_GRID_POINTS, *t_->gridPointsView)
      .read(QL_BIND_Q_CDF, *t_->q.cdfView)
      .write(QL_BIND_Q_SUM, *t_->q.sums)
      .write(QL_BIND_Q_COUNT, *t_->q.counts)
      .write(QL_BIND_SPAWN, *t_->spawn)
      .read(QL_BIND_V_CDF, *t_->v.cdfView)
      .write(QL_BIND_V_SUM, *t_->v.sums)
      .write(QL_BIND_V_COUNT, *t_->v.counts)
      .read(QL_BIND_POINT_UPDATES, *t_->pointUpdates);
}

render::GuidingBinder QGuiding::binder() const {
  render::GuidingBinder b;
  b.bind = [this](gpu::PassBuilder& pass) { bind(pass); };
  b.points = settings_.enabled;  // also when no point exists yet: camera paths spawn them
  b.lightLearning = pointCount_ > 0 && lightCount_ > 0 && settings_.enabled;
  return b;
}

void QGuiding::recordLearning(gpu::PassRecorder& rec) { recordTables(rec, pointCount_); }

void QGuiding::recordTables(gpu::PassRecorder& rec, uint32_t rows) {
  if (rows == 0) return;
  auto updateTable = [&](const char* name, const Table& table, uint32_t segment, bool cosine) {
    shared::TableUpdatePush push{rows * segment, segment, settings_.rows, settings_.cols,
                                 cosine ? 1u : 0u, settings_.alphaMin, settings_.alphaMax,
                                 settings_.qFloor};
    rec.pass(name, update_)
        .write(0, *table.values)
        .write(1, *table.visits)
        .write(2, *table.cdf)
        .write(3, *table.sums)
        .write(4, *table.counts)
        .write(5, *t_->pointUpdates)
        .push(push)
        .dispatchThreads(push.entries);
  };
  updateTable("guiding.q_update", t_->q, settings_.strata(), true);
  scan_.scanSegments(rec, *t_->q.cdf, rows, settings_.strata());
  // The light values are a points x lights table, far larger than Q for many
  // lights: they are updated every kLightUpdateInterval frames. Targets keep
  // accumulating in between and the batched update applies them all at once.
  if (lightCount_ > 0 && lightFrame_++ % kLightUpdateInterval == 0) {
    updateTable("guiding.v_update", t_->v, lightCount_, false);
    scan_.scanSegments(rec, *t_->v.cdf, rows, lightCount_);
  }
}

void QGuiding::afterFrame(ecs::Registry& registry) {
  if (!t_->acceptor) return;
  // Fixed slots (w = 1 where written this frame), read in slot order: the
  // points added do not depend on the GPU's timing.
  std::vector<glm::vec4> raw(kSpawnCapacity * 2ull);
  t_->spawn->download(ctx_, raw.data(), raw.size() * sizeof(glm::vec4));
  bool any = false;
  for (uint32_t i = 0; i < kSpawnCapacity && !any; ++i) any = raw[2 * i].w != 0.0f;
  if (!any) return;
  std::vector<glm::vec4> zeros(raw.size(), glm::vec4(0.0f));
  t_->spawn->upload(ctx_, zeros.data(), zeros.size() * sizeof(glm::vec4));
  uint32_t added = 0;
  for (uint32_t i = 0; i < kSpawnCapacity && pointCount_ + added < settings_.pointBudget; ++i) {
    if (raw[2 * i].w == 0.0f) continue;
    PointCandidate c{glm::vec3(raw[2 * i]), glm::vec3(raw[2 * i + 1]), 0.0f};
    CachePoint accepted;
    if (t_->acceptor->tryAccept(c, rejectionMin_, accepted)) {
      registry.emplace<CachePoint>(registry.create(), accepted);
      ++added;
    }
  }
  if (added == 0) return;
  spawned_ += added;
  uploadPoints(registry);  // their table rows already hold the initial distribution
}

GuidingStats QGuiding::stats() const {
  GuidingStats s;
  s.points = pointCount_;
  s.strata = settings_.strata();
  s.lightsLearned = lightCount_;
  s.rejectionMin = rejectionMin_;
  s.rejectionMax = rejectionMax_;
  s.searchRadius = searchRadius_;
  s.spawnedPoints = spawned_;
  return s;
}

std::vector<float> QGuiding::readQ(uint32_t point) const {
  std::vector<float> q(settings_.strata());
  if (point >= pointCount_) throw std::out_of_range("no cache point " + std::to_string(point));
  t_->q.values->download(ctx_, q.data(), q.size() * 4, uint64_t(point) * q.size() * 4);
  return q;
}

}  // namespace qlight::guiding
