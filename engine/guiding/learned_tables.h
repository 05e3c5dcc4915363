// What the guide has learned, per cache point slot, kept across frames as named
// GPU buffers: Q over the hemisphere's strata and the light values V over the
// lights (Dahm & Keller section 4), each with visit counts, the CDF the path
// passes sample, and the frame's target sums (64-bit fixed point, so the order
// of the atomics does not matter); and the Q updates each point has received
// (its confidence), and the shadow rays each point's NEE traced and those that got through
// (its learned NEE probability). The learning pass (shaders/q_update.comp: the update and the
// CDF of each row that received targets) runs after each frame's tracing.
#pragma once
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "engine/gpu/compute_pipeline.h"
#include "engine/gpu/pass_recorder.h"
#include "engine/guiding/guiding_settings.h"

namespace qlight::guiding {

// One learned table (Q over strata, or V over lights) and its frame accumulators.
struct LearnedTable {
  std::unique_ptr<gpu::Buffer> values, visits, cdf, sums, counts;
  // Direction trees only (Q with DirectionModel::Tree): each slot's child node, 0 for a leaf;
  // cdf then holds the slots' sampling weights.
  std::unique_ptr<gpu::Buffer> children;
  std::unique_ptr<gpu::BufferView> childrenView;  // a node's 4 slots a texel
  std::unique_ptr<gpu::Buffer> rowClocks;    // per row: the forgetting clock at its last update
  std::unique_ptr<gpu::BufferView> cdfView;  // the path passes read the CDF as a texel buffer
  uint32_t rowLength = 0;                    // entries per slot

  // tree: the rows are direction trees (4 slots a node; the views read a node a texel).
  void allocate(const gpu::Context& ctx, uint64_t slots, uint32_t rowLength,
                const std::string& name, bool tree = false);
  bool tree() const { return children != nullptr; }
  // Fills the rows [first, first + count) with `initial` values and no visits or targets.
  void recordReset(gpu::PassRecorder& rec, float initial, uint64_t first, uint64_t count) const;
  uint64_t memoryBytes() const;
};

class LearnedTables {
 public:
  explicit LearnedTables(const gpu::Context& ctx);

  // Fresh buffers for `slots` rows of Q entries (settings.entriesPerPoint(): strata or a
  // direction tree) and `lights` V entries (0: no V).
  void allocate(uint32_t slots, const GuidingSettings& settings, uint32_t lights);
  // Every row back to the start (uniform Q, V at the floor), with valid CDFs: points
  // added later start from a valid distribution without a learning pass of their own.
  void reset(const GuidingSettings& settings);
  // The rows of slots a new point took over from a destroyed one, with their CDFs (the
  // first `rows` rows are rebuilt; none of them has targets pending between frames).
  void recordResetRows(gpu::PassRecorder& rec, std::span<const uint32_t> slots, uint32_t rows,
                       const GuidingSettings& settings);
  // After the frame's tracing: the frame's targets applied to the first `rows` rows
  // (D&K eq. 5 with the batched learning rate), and the CDFs of the rows that had any.
  void recordLearning(gpu::PassRecorder& rec, uint32_t rows, const GuidingSettings& settings);
  // Tracking: `halvings` more for every row at the next learning pass (on top of the
  // half-life's 1 / halfLifeFrames a pass).
  void forget(float halvings) { pendingHalvings_ += halvings; }
  float pendingHalvings() const { return pendingHalvings_; }
  // Learned NEE's counts: `halvings` more at the next learning pass (on top of
  // kNeeForgetScale times the half-life's).
  void forgetNee(float halvings) { pendingNeeHalvings_ += halvings; }
  float pendingNeeHalvings() const { return pendingNeeHalvings_; }
  // Applies the pending halvings to the first `rows` rows now (their counts and CDFs, and
  // the NEE counts), in a submission of its own: for a jump, before the frame's paths read
  // the confidence and NEE's probability.
  void ageNow(uint32_t rows, const GuidingSettings& settings);

  uint32_t lights() const { return lights_; }
  uint64_t memoryBytes() const;  // GPU buffers
  const LearnedTable& q() const { return q_; }
  const LearnedTable& v() const { return v_; }
  // Read by the path passes as a texel buffer (the confidence of each point).
  const gpu::BufferView& pointUpdatesView() const { return *pointUpdatesView_; }
  // Learned NEE: each point's shadow rays and those unoccluded (shared::kNeeWordsPerPoint
  // words a point), counted by the trace pass.
  const gpu::Buffer& neeCounts() const { return *neeCounts_; }
  // Each slot's probability of sampling a light (shared::neeProbabilityOf), for tests and the
  // UI.
  std::vector<float> readNeeProbabilities(float minProbability) const;
  // The tree children the path passes bind: the Q table's, or a placeholder with strata.
  const gpu::BufferView& childrenView() const {
    return q_.tree() ? *q_.childrenView : *placeholderChildrenView_;
  }
  // Q of one slot (strata values; for trees every slot's Q, inner ones stale), for tests and
  // the UI.
  std::vector<float> readQ(uint32_t slot) const;
  // A slot's direction tree: its slots' sampling weights and children (trees only).
  struct TreeRow {
    std::vector<float> weights;
    std::vector<uint32_t> children;
  };
  TreeRow readTree(uint32_t slot) const;
  // Every slot's sampling weights (strata: the CDFs; trees: the slots' weights).
  std::vector<float> readAllWeights() const;
  // The light values V of one slot (empty without light learning), for the UI.
  std::vector<float> readV(uint32_t slot) const;
  // Every slot's Q and update count (the UI's overlay of all points).
  std::vector<float> readAllQ() const;
  std::vector<uint32_t> readPointUpdates() const;
  // Smallest and largest Q over every slot, and the entries that are not finite (the soak
  // run checks the tables stay finite and bounded).
  struct ValueRange {
    float min = 0, max = 0;
    uint64_t nonFinite = 0;
  };
  ValueRange qRange() const;

 private:
  // everyRow: also the rows without targets (their CDFs after a reset).
  void recordUpdate(gpu::PassRecorder& rec, const char* name, const LearnedTable& table,
                    uint32_t rows, bool cosineWeights, bool everyRow,
                    const GuidingSettings& settings);
  // The learned NEE counts: the frame's folded into the running ones, which keep `kept`.
  void recordNeeUpdate(gpu::PassRecorder& rec, uint32_t rows, float kept);

  const gpu::Context& ctx_;
  gpu::ComputePipeline update_, treeUpdate_, neeUpdate_;
  LearnedTable q_, v_;
  std::unique_ptr<gpu::Buffer> pointUpdates_, neeCounts_;
  std::unique_ptr<gpu::BufferView> pointUpdatesView_;
  std::unique_ptr<gpu::Buffer> placeholderChildren_;
  std::unique_ptr<gpu::BufferView> placeholderChildrenView_;
  uint32_t slots_ = 0, lights_ = 0;
  uint32_t learningPasses_ = 0;  // for the light-value update interval
  // The forgetting clock, in halvings: a row's counts are aged by the clock's advance since
  // its last update (2^-(clock - its clock)), lazily, when it next receives targets.
  double clock_ = 0.0;
  float pendingHalvings_ = 0.0f, pendingNeeHalvings_ = 0.0f;
  // The NEE counts' share kept after the half-life's `halfLifeHalvings` and the pending ones;
  // clears those.
  float takeNeeKept(double halfLifeHalvings);
};

}  // namespace qlight::guiding
