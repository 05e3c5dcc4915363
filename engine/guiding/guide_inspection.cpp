#include "engine/guiding/guide_inspection.h"

#include "engine/guiding/direction_tree_cpu.h"
#include "shaders/shared/strata.h"

namespace qlight::guiding {

std::vector<PointSummary> summarizePoints(ecs::Registry& registry, const QGuide& guide) {
  const GuidingSettings& s = guide.settings();
  const bool tree = s.directions == DirectionModel::Tree;
  // Strata: Q per stratum; trees: the slots' weights (the root's first, 4 a node).
  const std::vector<float> q = tree ? guide.tables().readAllWeights() : guide.tables().readAllQ();
  const uint32_t perPoint = s.entriesPerPoint();
  const std::vector<uint32_t> updates = guide.tables().readPointUpdates();
  std::vector<float> cosine(s.strata());
  for (uint32_t k = 0; k < s.strata(); ++k)
    cosine[k] = shared::stratumCosineIntegral(k, s.rows, s.cols);
  std::vector<PointSummary> out;
  registry.view<const CachePoint>().each([&](ecs::Entity, const CachePoint& p) {
    if (uint64_t(p.slot + 1) * perPoint > q.size()) return;
    PointSummary summary{p.position, p.normal};
    const float* row = &q[uint64_t(p.slot) * perPoint];
    if (tree)
      summary.irradiance = shared::kPi * 0.25f * (row[0] + row[1] + row[2] + row[3]);
    else
      for (uint32_t k = 0; k < s.strata(); ++k) summary.irradiance += row[k] * cosine[k];
    summary.confidence = shared::confidenceOf(updates[p.slot], s.confidenceUpdates, s.strata());
    out.push_back(summary);
  });
  return out;
}

std::optional<PointDetail> inspectPointAt(ecs::Registry& registry, const QGuide& guide,
                                          glm::vec3 position, glm::vec3 towardViewer) {
  const float reach = guide.searchRadius();
  std::optional<CachePoint> best;
  float bestDistance = reach * reach;
  registry.view<const CachePoint>().each([&](ecs::Entity, const CachePoint& p) {
    const glm::vec3 d = p.position - position;
    const float distance = glm::dot(d, d);
    if (distance <= bestDistance && glm::dot(p.normal, towardViewer) > 0.0f) {
      bestDistance = distance;
      best = p;
    }
  });
  if (!best) return std::nullopt;
  const GuidingSettings& s = guide.settings();
  std::vector<float> q;
  if (s.directions == DirectionModel::Tree) {
    LearnedTables::TreeRow row = guide.tables().readTree(best->slot);
    q = treeOnStrata(DirectionTree{std::move(row.weights), std::move(row.children)}, s.rows,
                     s.cols);
  } else {
    q = guide.tables().readQ(best->slot);
  }
  PointDetail detail{*best, s.rows, s.cols, std::move(q), guide.tables().readV(best->slot)};
  const std::vector<uint32_t> updates = guide.tables().readPointUpdates();
  detail.confidence = shared::confidenceOf(updates.at(best->slot), s.confidenceUpdates, s.strata());
  return detail;
}

PointDetail inspectNetworkAt(const DqnGuide& guide, glm::vec3 position, glm::vec3 normal) {
  const GuidingSettings& s = guide.settings();
  shared::DqnRecord state{guide.position01(position), 0, glm::normalize(normal), 0.0f};
  PointDetail detail{
      CachePoint{position, 0.0f, state.normal, 0}, s.rows, s.cols, guide.evaluate({state}), {}};
  detail.confidence = guide.stats().confidence;
  return detail;
}

}  // namespace qlight::guiding
