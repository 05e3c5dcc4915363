// The GPU learning pass (update and CDF per row) on a synthetic table equals a
// CPU reference of the formula (D&K eq. 5 with the batched learning rate)
// applied to the fixed-point target sums; the largest sum stays finite; rows
// without targets are left alone unless every row is asked for; with a half-life, the
// visit counts and the point's confidence age by the passes since the row's last update.
#include <cmath>
#include <limits>
#include <random>

#include "engine/gpu/pass_recorder.h"
#include "shaders/shared/guiding_types.h"
#include "shaders/shared/strata.h"
#include "tests/gpu/gpu_fixture.h"

namespace qlight::test {
namespace {

class QUpdateGpu : public GpuTest {};

// One table's buffers for `points` rows of `n` entries in all, and the learning pass over
// them as LearnedTables records it.
struct TableBuffers {
  gpu::Buffer q, visits, cdf, sums, counts, pointUpdates, rowClocks;
  TableBuffers(const gpu::Context& ctx, uint32_t n, uint32_t points)
      : q(ctx, n * 4, "q"),
        visits(ctx, n * 4, "visits"),
        cdf(ctx, n * 4, "cdf"),
        sums(ctx, n * 8, "sums"),
        counts(ctx, n * 4, "counts"),
        pointUpdates(ctx, points * 4, "pointUpdates"),
        rowClocks(ctx, points * 4, "rowClocks") {}
  void learningPass(const gpu::Context& ctx, const shared::TableUpdatePush& push) const {
    gpu::ComputePipeline update(ctx, "q_update");
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
      gpu::PassRecorder rec(ctx, cmd);
      rec.pass("q_update", update)
          .write(QL_Q_UPDATE_BIND_VALUES, q)
          .write(QL_Q_UPDATE_BIND_VISITS, visits)
          .write(QL_Q_UPDATE_BIND_CDF, cdf)
          .write(QL_Q_UPDATE_BIND_SUMS, sums)
          .write(QL_Q_UPDATE_BIND_COUNTS, counts)
          .write(QL_Q_UPDATE_BIND_POINT_UPDATES, pointUpdates)
          .write(QL_Q_UPDATE_BIND_ROW_CLOCKS, rowClocks)
          .push(push)
          .dispatch((push.rowCount + QL_Q_UPDATE_GROUP_SIZE - 1) / QL_Q_UPDATE_GROUP_SIZE);
      rec.finish();
    });
  }
};

TEST_F(QUpdateGpu, UpdateAndCdfMatchCpuReference) {
  const uint32_t points = 300, rows = 4, cols = 8, strata = rows * cols;
  const uint32_t n = points * strata;
  const float aMin = 1e-3f, aMax = 0.2f, qFloor = 1e-4f;
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> u(0.0f, 2.0f);
  std::vector<float> q(n), sums(n);
  std::vector<uint32_t> visits(n), counts(n), fixedSums(2 * n);
  for (uint32_t e = 0; e < n; ++e) {
    q[e] = u(rng);
    visits[e] = e % 3 == 0 ? 0 : rng() % 5000;  // a third never visited before
    // Every 7th point receives no target at all: the pass skips its row.
    counts[e] = e % 5 == 0 || (e / strata) % 7 == 3 ? 0 : rng() % 40;
    // The frame's targets as the shader sums them: 64-bit fixed point, 20 fraction bits.
    uint64_t fixed = uint64_t(double(counts[e]) * u(rng) * 3.0 * shared::kTargetScale);
    fixedSums[2 * e] = uint32_t(fixed);
    fixedSums[2 * e + 1] = uint32_t(fixed >> 32);
    sums[e] = shared::fixedSumToFloat(fixedSums[2 * e], fixedSums[2 * e + 1]);
  }
  // The largest sum the fixed point can hold stays finite.
  fixedSums[14] = fixedSums[15] = 0xffffffffu;
  counts[7] = 1;
  sums[7] = shared::fixedSumToFloat(0xffffffffu, 0xffffffffu);

  TableBuffers t(ctx(), n, points);
  gpu::Buffer &bq = t.q, &bv = t.visits, &bc = t.cdf, &bs = t.sums, &bn = t.counts,
              &bp = t.pointUpdates, &br = t.rowClocks;
  std::vector<uint32_t> noUpdates(points, 0);
  const float kUntouched = -1.0f;  // CDF sentinel: rows the pass skips keep it
  bc.upload<float>(ctx(), std::vector<float>(n, kUntouched));
  bp.upload<uint32_t>(ctx(), noUpdates);
  br.upload<uint32_t>(ctx(), noUpdates);
  bq.upload<float>(ctx(), q);
  bv.upload<uint32_t>(ctx(), visits);
  bs.upload<uint32_t>(ctx(), fixedSums);
  bn.upload<uint32_t>(ctx(), counts);
  auto learningPass = [&](uint32_t everyRow) {
    t.learningPass(ctx(), {points, strata, rows, cols, 1, aMin, aMax, qFloor, everyRow});
  };
  learningPass(0);
  auto skipped = bc.read<float>(ctx());
  for (uint32_t p = 3; p < points; p += 7)
    for (uint32_t k = 0; k < strata; ++k)
      ASSERT_EQ(skipped[p * strata + k], kUntouched) << "point " << p << " has no targets";
  learningPass(1);  // nothing left to apply: only the skipped rows' CDFs are new
  auto gq = bq.read<float>(ctx());
  auto gv = bv.read<uint32_t>(ctx());
  auto gc = bc.read<float>(ctx());
  auto gs = bs.read<uint32_t>(ctx());
  auto gn = bn.read<uint32_t>(ctx());
  auto gp = bp.read<uint32_t>(ctx());
  for (uint32_t p = 0; p < points; ++p) {
    uint32_t pointTotal = 0;
    for (uint32_t k = 0; k < strata; ++k) pointTotal += counts[p * strata + k];
    ASSERT_EQ(gp[p], pointTotal) << "updates of point " << p;
    // Sampling weights: Q shrunk toward the mean of the row's visited strata.
    double visitedSum = 0;
    uint32_t visitedCount = 0;
    for (uint32_t k = 0; k < strata; ++k)
      if (gv[p * strata + k] > 0) {
        visitedSum += std::max(gq[p * strata + k], qFloor);
        ++visitedCount;
      }
    double cdf = 0;
    for (uint32_t k = 0; k < strata; ++k) {
      uint32_t e = p * strata + k;
      // Entries without targets are left as they are (the CDF weighs them at least the floor).
      float expected =
          counts[e] ? shared::updatedQ(q[e], sums[e], counts[e], visits[e], aMin, aMax, qFloor)
                    : q[e];
      ASSERT_TRUE(std::isfinite(gq[e])) << e;
      // GLSL's pow is exp2(y log2 x) with log2 good to 2^-21 absolute, so the
      // retained fraction after m updates is good to about m 2^-21 relative;
      // it scales the distance between the old value and the targets' mean.
      double mean = counts[e] ? double(sums[e]) / counts[e] : q[e];
      double spread = std::isfinite(mean) ? std::abs(q[e] - mean) : 0.0;
      double tolerance =
          spread * (counts[e] + 1) * std::ldexp(1.0, -20) + 2e-6 * std::max(1.0f, expected);
      ASSERT_NEAR(gq[e], expected, tolerance) << "entry " << e;
      ASSERT_EQ(gv[e], visits[e] + counts[e]);
      ASSERT_EQ(gs[2 * e], 0u);
      ASSERT_EQ(gs[2 * e + 1], 0u);
      ASSERT_EQ(gn[e], 0u);
      // Shrunk toward the row's visited mean by 4 pseudo-visits (q_update.comp).
      double q = std::max(double(gq[e]), double(qFloor)), n = gv[e];
      double weight = visitedCount > 0 ? (n * q + 4.0 * visitedSum / visitedCount) / (n + 4.0) : q;
      cdf += weight * shared::stratumCosineIntegral(k, rows, cols);  // the scan of the update
      ASSERT_NEAR(gc[e], cdf, 1e-5 * cdf) << "cdf of entry " << e;
    }
  }
  EXPECT_TRUE(std::isfinite(gq[7]));
}

// Tracking: a row updated when the forgetting clock reads 3.6 halvings, last updated at 2.0,
// first ages its point's update count by 2^-1.6 and its visit counts by the square of that
// (Q forgets twice as fast as the confidence), then learns with the aged counts (a higher
// learning rate); a row without targets keeps its counts (and clock) until it is used.
TEST_F(QUpdateGpu, CountsAgeByTheClocksAdvanceSinceTheRowsLastUpdate) {
  const uint32_t points = 2, rows = 2, cols = 2, strata = rows * cols, n = points * strata;
  const float aMin = 1e-4f, aMax = 1.0f, qFloor = 1e-4f;
  const float lastClock = 2.0f, clock = 3.6f;
  std::vector<float> q{1.0f, 1.0f, 1.0f, 1.0f, 0.5f, 0.5f, 0.5f, 0.5f};
  std::vector<uint32_t> visits{1000, 400, 0, 77, 1000, 1000, 1000, 1000};
  std::vector<uint32_t> counts{4, 0, 2, 0, 0, 0, 0, 0};  // point 1: no targets
  std::vector<uint32_t> fixedSums(2 * n, 0), pointUpdates{900, 900};
  std::vector<float> rowClocks{lastClock, lastClock};
  fixedSums[0] = uint32_t(4 * 3.0 * shared::kTargetScale);  // 4 targets of 3
  fixedSums[4] = uint32_t(2 * 2.0 * shared::kTargetScale);  // 2 targets of 2
  TableBuffers t(ctx(), n, points);
  gpu::Buffer &bq = t.q, &bv = t.visits, &bc = t.cdf, &bs = t.sums, &bn = t.counts,
              &bp = t.pointUpdates, &br = t.rowClocks;
  bq.upload<float>(ctx(), q);
  bv.upload<uint32_t>(ctx(), visits);
  bc.upload<float>(ctx(), std::vector<float>(n, 0.0f));
  bs.upload<uint32_t>(ctx(), fixedSums);
  bn.upload<uint32_t>(ctx(), counts);
  bp.upload<uint32_t>(ctx(), pointUpdates);
  br.upload<float>(ctx(), rowClocks);
  t.learningPass(ctx(), {points, strata, rows, cols, 1, aMin, aMax, qFloor, 0, clock});
  auto gq = bq.read<float>(ctx());
  auto gv = bv.read<uint32_t>(ctx());
  auto gp = bp.read<uint32_t>(ctx());
  auto gr = br.read<float>(ctx());
  const double keep = std::exp2(double(lastClock) - double(clock));  // 0.33
  auto aged = [&](uint32_t c) { return uint32_t(double(c) * keep); };
  auto agedVisits = [&](uint32_t c) { return uint32_t(double(c) * keep * keep); };
  EXPECT_EQ(gr[0], clock);
  EXPECT_EQ(gr[1], lastClock) << "a row without targets is not touched";
  EXPECT_EQ(gp[0], aged(900) + 6);
  EXPECT_EQ(gp[1], 900u);
  for (uint32_t k = 0; k < strata; ++k) EXPECT_EQ(gv[k], agedVisits(visits[k]) + counts[k]) << k;
  for (uint32_t k = strata; k < n; ++k) EXPECT_EQ(gv[k], visits[k]) << k;
  // Stratum 0: 4 targets of 3 after 1000 visits aged to 108: the running mean over 112.
  const double n0 = agedVisits(1000);
  EXPECT_NEAR(gq[0], (n0 * 1.0 + 4 * 3.0) / (n0 + 4), 1e-5);
  // Without the aging the same update would have moved Q about 9x less.
  EXPECT_GT(gq[0] - 1.0, 8.0 * ((1000.0 + 12.0) / 1004.0 - 1.0));
  EXPECT_NEAR(gq[2], 2.0f, 1e-6) << "a first visit takes the targets' mean";
  EXPECT_FLOAT_EQ(gq[1], 1.0f);
}

// A point's update count stops where its confidence is full (confidenceUpdates x strata), so
// after a light's jump the aged count is the share of full confidence that the forgetting
// kept, however long the point had been learning before.
TEST_F(QUpdateGpu, PointUpdateCountsStopAtFullConfidence) {
  const uint32_t points = 3, rows = 2, cols = 2, strata = rows * cols, n = points * strata;
  const float confidenceUpdates = 4.0f;
  const uint32_t cap = shared::confidenceCapOf(confidenceUpdates, strata);
  ASSERT_EQ(cap, 16u);
  EXPECT_EQ(shared::confidenceCapOf(0.0f, strata), 0u) << "trusting at once needs no cap";
  std::vector<uint32_t> counts(n, 0), pointUpdates{10, 15, 5000};
  counts[0] = 2;                                    // point 0: 10 + 2 stays below the cap
  counts[strata] = 3;                               // point 1: 15 + 3 stops at 16
  counts[2 * strata] = counts[2 * strata + 1] = 1;  // point 2: a count from before the cap
  std::vector<uint32_t> fixedSums(2 * n, 0);
  for (uint32_t e = 0; e < n; ++e) fixedSums[2 * e] = uint32_t(counts[e] * shared::kTargetScale);
  TableBuffers t(ctx(), n, points);
  t.q.upload<float>(ctx(), std::vector<float>(n, 1.0f));
  t.visits.upload<uint32_t>(ctx(), std::vector<uint32_t>(n, 10));
  t.cdf.upload<float>(ctx(), std::vector<float>(n, 0.0f));
  t.sums.upload<uint32_t>(ctx(), fixedSums);
  t.counts.upload<uint32_t>(ctx(), counts);
  t.pointUpdates.upload<uint32_t>(ctx(), pointUpdates);
  t.rowClocks.upload<float>(ctx(), std::vector<float>(points, 0.0f));
  shared::TableUpdatePush push{points, strata, rows, cols, 1, 1e-4f, 1.0f, 1e-4f, 0, 0.0f};
  push.confidenceCap = cap;
  t.learningPass(ctx(), push);
  const auto capped = t.pointUpdates.read<uint32_t>(ctx());
  EXPECT_EQ(capped[0], 12u);
  EXPECT_EQ(capped[1], cap);
  EXPECT_EQ(capped[2], cap);
  // The same pass with a jump of 4 halvings since the rows' last update: 1/16 of full.
  t.pointUpdates.upload<uint32_t>(ctx(), std::vector<uint32_t>(points, 5000));
  t.counts.upload<uint32_t>(ctx(), counts);
  t.sums.upload<uint32_t>(ctx(), fixedSums);
  push.clock = 4.0f;
  t.learningPass(ctx(), push);
  const auto aged = t.pointUpdates.read<uint32_t>(ctx());
  EXPECT_EQ(aged[0], cap) << "5000 aged to 312, plus 2, capped";
  t.pointUpdates.upload<uint32_t>(ctx(), std::vector<uint32_t>(points, cap));
  t.counts.upload<uint32_t>(ctx(), counts);
  t.sums.upload<uint32_t>(ctx(), fixedSums);
  t.rowClocks.upload<float>(ctx(), std::vector<float>(points, 0.0f));
  t.learningPass(ctx(), push);
  const auto agedFromFull = t.pointUpdates.read<uint32_t>(ctx());
  EXPECT_EQ(agedFromFull[0], 1u + 2u) << "full confidence aged 4 halvings keeps 1/16";
  EXPECT_EQ(agedFromFull[1], 1u + 3u);
}

}  // namespace
}  // namespace qlight::test
