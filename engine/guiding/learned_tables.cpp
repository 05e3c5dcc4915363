#include "engine/guiding/learned_tables.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "shaders/shared/guiding_types.h"

namespace qlight::guiding {
namespace {

// The light values are a points x lights table, far larger than Q for many lights: they
// are updated every kLightUpdateInterval frames. Targets keep accumulating in between and
// the batched update applies them all at once.
constexpr uint32_t kLightUpdateInterval = 4;
// Workgroups along x every Vulkan device supports; more rows continue in y.
constexpr uint32_t kMaxGroupsX = 65535;

uint32_t floatBits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, 4);
  return u;
}

std::unique_ptr<gpu::Buffer> makeTableBuffer(const gpu::Context& ctx, uint64_t bytes,
                                             const std::string& name) {
  return std::make_unique<gpu::Buffer>(ctx, std::max<uint64_t>(bytes, 16), name,
                                       gpu::kTexelTableUsage);
}

}  // namespace

void LearnedTable::allocate(const gpu::Context& ctx, uint64_t slots, uint32_t length,
                            const std::string& name, bool tree) {
  rowLength = length;
  const uint64_t entries = std::max<uint64_t>(slots * length, 1);
  // The 64-bit sums are the largest buffer of a table.
  ctx.requireBufferFits("the " + name + " table (" + std::to_string(slots) + " points x " +
                            std::to_string(length) + " entries; lower --points or --strata)",
                        entries * 8, true, entries);
  cdfView.reset();
  childrenView.reset();
  children.reset();
  values = makeTableBuffer(ctx, entries * 4, name + ".values");
  visits = makeTableBuffer(ctx, entries * 4, name + ".visits");
  cdf = makeTableBuffer(ctx, entries * 4, name + ".cdf");
  sums = makeTableBuffer(ctx, entries * 8, name + ".sums");  // 64-bit fixed point per entry
  counts = makeTableBuffer(ctx, entries * 4, name + ".counts");
  rowClocks = makeTableBuffer(ctx, std::max<uint64_t>(slots, 1) * 4, name + ".rowClocks");
  if (tree) {
    children = makeTableBuffer(ctx, entries * 4, name + ".children");
    cdfView = std::make_unique<gpu::BufferView>(ctx, *cdf, VK_FORMAT_R32G32B32A32_SFLOAT);
    childrenView = std::make_unique<gpu::BufferView>(ctx, *children, VK_FORMAT_R32G32B32A32_UINT);
  } else {
    cdfView = std::make_unique<gpu::BufferView>(ctx, *cdf, VK_FORMAT_R32_SFLOAT);
  }
}

void LearnedTable::recordReset(gpu::PassRecorder& rec, float initial, uint64_t first,
                               uint64_t count) const {
  const uint64_t firstEntry = first * rowLength, entries = count * rowLength;
  if (entries == 0) return;  // an empty table (V without learned lights)
  const bool whole = first == 0 && entries * 4 >= values->size();
  auto fill = [&](const gpu::Buffer& b, uint32_t value, uint64_t entryBytes) {
    if (whole)
      rec.fill("guiding.reset", b, value);
    else
      rec.fill("guiding.reset", b, value, firstEntry * entryBytes, entries * entryBytes);
  };
  fill(*values, floatBits(initial), 4);
  fill(*visits, 0, 4);
  fill(*sums, 0, 8);
  fill(*counts, 0, 4);
  fill(*cdf, 0, 4);
  if (children) fill(*children, 0, 4);  // every tree back to a root of 4 leaves
  // A reset row has nothing to age, so its clock only needs a defined start.
  if (whole) rec.fill("guiding.reset", *rowClocks, 0);
}

uint64_t LearnedTable::memoryBytes() const {
  return values->size() + visits->size() + cdf->size() + sums->size() + counts->size() +
         rowClocks->size() + (children ? children->size() : 0);
}

uint64_t LearnedTables::memoryBytes() const {
  return q_.memoryBytes() + v_.memoryBytes() + pointUpdates_->size() + neeCounts_->size();
}

LearnedTables::LearnedTables(const gpu::Context& ctx)
    : ctx_(ctx),
      update_(ctx, "q_update"),
      treeUpdate_(ctx, "q_tree_update"),
      neeUpdate_(ctx, "nee_update") {
  placeholderChildren_ = makeTableBuffer(ctx_, 16, "guiding.q.noChildren");
  placeholderChildren_->upload(ctx_, std::vector<uint32_t>(4, 0).data(), 16);
  placeholderChildrenView_ =
      std::make_unique<gpu::BufferView>(ctx_, *placeholderChildren_, VK_FORMAT_R32G32B32A32_UINT);
}

void LearnedTables::allocate(uint32_t slots, const GuidingSettings& settings, uint32_t lights) {
  slots_ = slots;
  lights_ = lights;
  q_.allocate(ctx_, slots, settings.entriesPerPoint(), "guiding.q",
              settings.directions == DirectionModel::Tree);
  v_.allocate(ctx_, slots, lights, "guiding.v");
  if (!pointUpdates_ || pointUpdates_->size() < std::max<uint64_t>(uint64_t(slots) * 4, 16)) {
    pointUpdatesView_.reset();
    pointUpdates_ = makeTableBuffer(ctx_, uint64_t(slots) * 4, "guiding.pointUpdates");
    pointUpdatesView_ = std::make_unique<gpu::BufferView>(ctx_, *pointUpdates_, VK_FORMAT_R32_UINT);
  }
  const uint64_t neeBytes = std::max<uint64_t>(uint64_t(slots) * shared::kNeeWordsPerPoint * 4, 16);
  if (!neeCounts_ || neeCounts_->size() < neeBytes)
    neeCounts_ = std::make_unique<gpu::Buffer>(ctx_, neeBytes, "guiding.neeCounts");
}

void LearnedTables::reset(const GuidingSettings& settings) {
  // Uniform Q (cosine sampling), no visits; the update pass over every row, with no
  // targets, then writes every slot's CDF.
  ctx_.submitAndWait([&](VkCommandBuffer cmd) {
    gpu::PassRecorder rec(ctx_, cmd);
    q_.recordReset(rec, settings.initialQ, 0, slots_);
    rec.fill("guiding.reset", *pointUpdates_, 0);
    rec.fill("guiding.reset", *neeCounts_, 0);  // no rays yet: NEE at every vertex
    // Light values start at the floor: until a light has shown a contribution at a point,
    // NEE picks it by power (the mixture), not uniformly among all lights.
    v_.recordReset(rec, settings.qFloor, 0, slots_);
    recordUpdate(rec, "guiding.q_update", q_, slots_, true, true, settings);
    if (lights_ > 0) recordUpdate(rec, "guiding.v_update", v_, slots_, false, true, settings);
    rec.finish();
  });
}

void LearnedTables::recordResetRows(gpu::PassRecorder& rec, std::span<const uint32_t> slots,
                                    uint32_t rows, const GuidingSettings& settings) {
  if (slots.empty()) return;
  for (uint32_t slot : slots) {
    q_.recordReset(rec, settings.initialQ, slot, 1);
    if (lights_ > 0) v_.recordReset(rec, settings.qFloor, slot, 1);
    rec.fill("guiding.reset", *pointUpdates_, 0, uint64_t(slot) * 4, 4);
    constexpr uint64_t kNeeBytes = shared::kNeeWordsPerPoint * 4;
    rec.fill("guiding.reset", *neeCounts_, 0, uint64_t(slot) * kNeeBytes, kNeeBytes);
  }
  recordUpdate(rec, "guiding.q_cdf", q_, rows, true, true, settings);
  if (lights_ > 0) recordUpdate(rec, "guiding.v_cdf", v_, rows, false, true, settings);
}

void LearnedTables::recordUpdate(gpu::PassRecorder& rec, const char* name,
                                 const LearnedTable& table, uint32_t rows, bool cosineWeights,
                                 bool everyRow, const GuidingSettings& settings) {
  if (rows == 0 || table.rowLength == 0) return;
  const uint32_t groups = (rows + QL_Q_UPDATE_GROUP_SIZE - 1) / QL_Q_UPDATE_GROUP_SIZE;
  // Both passes share the table's bindings; trees add their children and their own push.
  gpu::PassBuilder pass = rec.pass(name, table.tree() ? treeUpdate_ : update_);
  pass.write(QL_Q_UPDATE_BIND_VALUES, *table.values)
      .write(QL_Q_UPDATE_BIND_VISITS, *table.visits)
      .write(QL_Q_UPDATE_BIND_CDF, *table.cdf)
      .write(QL_Q_UPDATE_BIND_SUMS, *table.sums)
      .write(QL_Q_UPDATE_BIND_COUNTS, *table.counts)
      .write(QL_Q_UPDATE_BIND_POINT_UPDATES, *pointUpdates_)
      .write(QL_Q_UPDATE_BIND_ROW_CLOCKS, *table.rowClocks);
  if (table.tree()) {
    shared::TreeUpdatePush push{};
    push.rowCount = rows;
    push.nodes = table.rowLength / 4;
    push.alphaMin = settings.alphaMin;
    push.alphaMax = settings.alphaMax;
    push.floorValue = settings.qFloor;
    push.everyRow = everyRow ? 1u : 0u;
    push.clock = float(clock_);
    push.splitShare = settings.treeSplitShare;
    push.splitVisits = settings.treeSplitVisits;
    push.maxDepth = settings.treeMaxDepth;
    push.confidenceCap = shared::confidenceCapOf(settings.confidenceUpdates, settings.strata());
    pass.write(QL_Q_UPDATE_BIND_CHILDREN, *table.children).push(push);
  } else {
    shared::TableUpdatePush push{};
    push.rowCount = rows;
    push.segmentLength = table.rowLength;
    push.rows = settings.rows;
    push.cols = settings.cols;
    push.cosineWeights = cosineWeights ? 1u : 0u;
    push.alphaMin = settings.alphaMin;
    push.alphaMax = settings.alphaMax;
    push.floorValue = settings.qFloor;
    push.everyRow = everyRow ? 1u : 0u;
    push.clock = float(clock_);
    push.confidenceCap = shared::confidenceCapOf(settings.confidenceUpdates, settings.strata());
    pass.push(push);
  }
  pass.dispatch(std::min(groups, kMaxGroupsX), (groups + kMaxGroupsX - 1) / kMaxGroupsX);
}

void LearnedTables::recordNeeUpdate(gpu::PassRecorder& rec, uint32_t rows, float kept) {
  if (rows == 0) return;
  shared::NeeUpdatePush push{};
  push.rowCount = rows;
  push.kept = kept;
  const uint32_t groups = (rows + QL_NEE_UPDATE_GROUP_SIZE - 1) / QL_NEE_UPDATE_GROUP_SIZE;
  rec.pass("guiding.nee_update", neeUpdate_)
      .write(QL_NEE_UPDATE_BIND_COUNTS, *neeCounts_)
      .push(push)
      .dispatch(std::min(groups, kMaxGroupsX), (groups + kMaxGroupsX - 1) / kMaxGroupsX);
}

float LearnedTables::takeNeeKept(double halfLifeHalvings) {
  const float kept =
      shared::keptAfter(float(shared::kNeeForgetScale * halfLifeHalvings) + pendingNeeHalvings_);
  pendingNeeHalvings_ = 0.0f;
  return kept;
}

void LearnedTables::recordLearning(gpu::PassRecorder& rec, uint32_t rows,
                                   const GuidingSettings& settings) {
  const double halfLife = settings.halfLifeFrames > 0 ? 1.0 / settings.halfLifeFrames : 0.0;
  const double halvings = halfLife + pendingHalvings_;
  clock_ += halvings;
  pendingHalvings_ = 0.0f;
  const float neeKept = takeNeeKept(halfLife);
  if (settings.learnsNee()) recordNeeUpdate(rec, rows, neeKept);
  recordUpdate(rec, "guiding.q_update", q_, rows, true, false, settings);
  if (lights_ > 0 && learningPasses_ % kLightUpdateInterval == 0)
    recordUpdate(rec, "guiding.v_update", v_, rows, false, false, settings);
  ++learningPasses_;
}

void LearnedTables::ageNow(uint32_t rows, const GuidingSettings& settings) {
  const bool ageQ = pendingHalvings_ > 0.0f;
  const float neeKept = takeNeeKept(0.0);
  clock_ += pendingHalvings_;
  pendingHalvings_ = 0.0f;
  // With no targets pending, the pass over every row only ages it and rebuilds its CDF.
  ctx_.submitAndWait([&](VkCommandBuffer cmd) {
    gpu::PassRecorder rec(ctx_, cmd);
    if (ageQ) {
      recordUpdate(rec, "guiding.q_age", q_, rows, true, true, settings);
      if (lights_ > 0) recordUpdate(rec, "guiding.v_age", v_, rows, false, true, settings);
    }
    if (settings.learnsNee()) recordNeeUpdate(rec, rows, neeKept);
    rec.finish();
  });
}

LearnedTables::ValueRange LearnedTables::qRange() const {
  const std::vector<float> q = readAllQ();
  ValueRange r;
  if (q.empty()) return r;
  r.min = INFINITY;
  r.max = -INFINITY;
  for (float v : q) {
    if (!std::isfinite(v)) {
      ++r.nonFinite;
      continue;
    }
    r.min = std::min(r.min, v);
    r.max = std::max(r.max, v);
  }
  return r;
}

namespace {
std::vector<float> readRow(const gpu::Context& ctx, const LearnedTable& table, uint32_t slot,
                           uint32_t slots) {
  if (slot >= slots) throw std::out_of_range("no cache point slot " + std::to_string(slot));
  std::vector<float> row(table.rowLength);
  if (!row.empty())
    table.values->download(ctx, row.data(), row.size() * 4, uint64_t(slot) * row.size() * 4);
  return row;
}
}  // namespace

std::vector<float> LearnedTables::readQ(uint32_t slot) const {
  return readRow(ctx_, q_, slot, slots_);
}

LearnedTables::TreeRow LearnedTables::readTree(uint32_t slot) const {
  if (!q_.tree()) throw std::logic_error("readTree: Q is not a direction tree");
  if (slot >= slots_) throw std::out_of_range("no cache point slot " + std::to_string(slot));
  TreeRow row;
  const uint64_t n = q_.rowLength, offset = uint64_t(slot) * n * 4;
  row.weights.resize(n);
  row.children.resize(n);
  q_.cdf->download(ctx_, row.weights.data(), n * 4, offset);
  q_.children->download(ctx_, row.children.data(), n * 4, offset);
  return row;
}

std::vector<float> LearnedTables::readAllWeights() const {
  std::vector<float> w(uint64_t(slots_) * q_.rowLength);
  if (!w.empty()) q_.cdf->download(ctx_, w.data(), w.size() * 4, 0);
  return w;
}

std::vector<float> LearnedTables::readV(uint32_t slot) const {
  return lights_ > 0 ? readRow(ctx_, v_, slot, slots_) : std::vector<float>{};
}

std::vector<float> LearnedTables::readAllQ() const {
  std::vector<float> q(uint64_t(slots_) * q_.rowLength);
  if (!q.empty()) q_.values->download(ctx_, q.data(), q.size() * 4, 0);
  return q;
}

std::vector<float> LearnedTables::readNeeProbabilities(float minProbability) const {
  std::vector<uint32_t> words(uint64_t(slots_) * shared::kNeeWordsPerPoint);
  if (!words.empty()) neeCounts_->download(ctx_, words.data(), words.size() * 4, 0);
  std::vector<float> p(slots_);
  for (uint32_t i = 0; i < slots_; ++i) {
    float running[2];
    std::memcpy(running, &words[uint64_t(i) * shared::kNeeWordsPerPoint + 2], sizeof(running));
    p[i] = shared::neeProbabilityOf(running[0], running[1], minProbability);
  }
  return p;
}

std::vector<uint32_t> LearnedTables::readPointUpdates() const {
  std::vector<uint32_t> n(slots_);
  if (!n.empty()) pointUpdates_->download(ctx_, n.data(), n.size() * 4, 0);
  return n;
}

}  // namespace qlight::guiding
