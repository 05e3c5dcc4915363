#include "engine/guiding/q_guide.h"

#include <cstdio>
#include <stdexcept>

#include "engine/guiding/guide_bindings.h"
#include "shaders/shared/strata.h"

namespace qlight::guiding {
namespace {

constexpr uint64_t kMaxLightEntries = 4u << 20;  // points x lights for light learning

// Lights with learned values: all of them when the table fits, else none (with a message).
uint32_t learnedLightCount(const GuidingSettings& s, uint32_t sceneLights) {
  if (!s.lightLearning || sceneLights <= 1) return 0;
  if (sceneLights <= shared::kMaxStrata &&  // a row of the learning pass, like the strata
      uint64_t(sceneLights) * s.pointBudget <= kMaxLightEntries)
    return sceneLights;
  std::fprintf(stderr,
               "qlight: light-selection learning off: %u lights x %u points exceeds its table\n",
               sceneLights, s.pointBudget);
  return 0;
}

}  // namespace

QGuide::QGuide(const gpu::Context& ctx, const GuidingSettings& settings)
    : ctx_(ctx),
      settings_(settings),
      generator_(ctx),
      tables_(ctx),
      uniforms_(ctx, sizeof(shared::GuidingUniforms), "guiding.uniforms", 0,
                gpu::MemoryUse::HostVisible) {
  validate(settings_);
  if (settings_.pointBudget == 0)  // the owner knows the frame: resolvedPointBudget
    throw std::invalid_argument("QGuide needs a resolved point budget");
  // Bindable before the first generatePoints: an empty set and tables, everything off.
  points_ = std::make_unique<CachePointSet>(ctx_, settings_.pointBudget, 0.0f);
  tables_.allocate(settings_.pointBudget, settings_, 0);
  writeUniforms();
}

void QGuide::setSettings(const GuidingSettings& s) {
  validate(s);
  if (s.pointBudget == 0) throw std::invalid_argument("QGuide needs a resolved point budget");
  GuidingSettings old = settings_;
  settings_ = s;
  bool pointsChanged = s.pointBudget != old.pointBudget || s.rejectionMin != old.rejectionMin ||
                       s.rejectionMax != old.rejectionMax || s.pointSet != old.pointSet ||
                       s.normalCosine != old.normalCosine || s.dartPaths != old.dartPaths ||
                       s.dartBounces != old.dartBounces || s.seed != old.seed ||
                       s.lightLearning != old.lightLearning;
  bool tablesChanged = s.rows != old.rows || s.cols != old.cols || s.initialQ != old.initialQ ||
                       s.qFloor != old.qFloor || s.directions != old.directions ||
                       s.treeNodes != old.treeNodes;
  if (pointsChanged) {
    needsPoints_ = true;
  } else if (tablesChanged) {
    tables_.allocate(points_->budget(), settings_, tables_.lights());
    tables_.reset(settings_);
  }
  writeUniforms();
}

void QGuide::generatePoints(ecs::Registry& registry, const render::GpuScene& scene) {
  points_->clear(registry);
  uint32_t lights = learnedLightCount(settings_, scene.lightCount());
  spawned_ = 0;
  radii_ = choosePointRadii(settings_, scene.surfaceArea());
  points_ = std::make_unique<CachePointSet>(ctx_, settings_.pointBudget, radii_.searchRadius);
  tables_.allocate(settings_.pointBudget, settings_, lights);
  generator_.throwDarts(registry, scene, settings_, radii_, settings_.seed + 7919u * ++generation_,
                        *points_);
  needsPoints_ = false;
  tables_.reset(settings_);
  uploadPoints(registry);
}

void QGuide::acceptSpawns(ecs::Registry& registry) {
  spawned_ += generator_.acceptSpawns(registry, radii_, *points_);
}

void QGuide::uploadPoints(ecs::Registry& registry) {
  CachePointSet::SyncResult sync = points_->sync(registry);
  if (!sync.reusedSlots.empty())
    ctx_.submitAndWait([&](VkCommandBuffer cmd) {
      gpu::PassRecorder rec(ctx_, cmd);
      tables_.recordResetRows(rec, sync.reusedSlots, points_->slotEnd(), settings_);
      rec.finish();
    });
  if (sync.changed) writeUniforms();  // the point count and the spawn switch follow the set
}

void QGuide::writeUniforms() {
  const uint32_t count = points_->count();
  shared::GuidingUniforms u{};
  u.rows = settings_.rows;
  u.cols = settings_.cols;
  u.pointCount = count;
  bool on = settings_.enabled && count > 0;
  u.flags = 0;
  if (on) u.flags |= shared::kGuideSample;
  if (on && settings_.learn) u.flags |= shared::kGuideLearn;
  if (settings_.target == LearningTarget::Returns) u.flags |= shared::kGuideLearnReturns;
  if (settings_.directions == DirectionModel::Tree) u.flags |= shared::kGuideTree;
  u.treeNodes = settings_.treeNodes;
  if (on && tables_.lights() > 0) u.flags |= shared::kGuideLightLearn;
  if (on && settings_.learnsNee()) u.flags |= shared::kGuideNeeLearn;
  if (on && settings_.guidedRoulette) u.flags |= shared::kGuideRoulette;
  u.neeMinProbability = settings_.neeMinProbability;
  if (settings_.enabled && settings_.spawnFromCamera && count < settings_.pointBudget &&
      generator_.spawning())
    u.flags |= shared::kGuideSpawn;
  u.searchRadius = radii_.searchRadius;
  u.cellSize = points_->grid().cellSize;
  u.hashSize = points_->grid().hashSize;
  u.selectProbability = settings_.selectProbability;
  u.normalCosine = settings_.normalCosine;
  u.qFloor = settings_.qFloor;
  u.lightMix = settings_.lightMix;
  u.lightCount = tables_.lights();
  u.spawnCapacity = PointGenerator::kSpawnCapacity;
  u.alphaMin = settings_.alphaMin;
  u.alphaMax = settings_.alphaMax;
  u.confidenceUpdates = settings_.confidenceUpdates;
  uniforms_.upload(ctx_, &u, sizeof(u));
}

void QGuide::bind(gpu::PassBuilder& pass) const {
  GuideBuffers b;
  b.uniforms = &uniforms_;
  b.points = &points_->pointsView();
  b.gridBuckets = &points_->gridBucketsView();
  b.gridPoints = &points_->gridPointsView();
  b.qCdf = tables_.q().cdfView.get();
  b.qChildren = &tables_.childrenView();
  b.qSums = tables_.q().sums.get();
  b.qCounts = tables_.q().counts.get();
  b.spawnReports = &generator_.spawnReports();
  b.vCdf = tables_.v().cdfView.get();
  b.vSums = tables_.v().sums.get();
  b.vCounts = tables_.v().counts.get();
  b.pointUpdates = &tables_.pointUpdatesView();
  b.neeCounts = &tables_.neeCounts();
  bindGuideBuffers(pass, b);
}

render::GuideFeatures QGuide::features() const {
  render::GuideFeatures f;
  f.points = settings_.enabled;  // also when no point exists yet: camera paths spawn them
  f.lightLearning = settings_.enabled && points_->count() > 0 && tables_.lights() > 0;
  f.directionTrees = settings_.directions == DirectionModel::Tree;
  f.tdTarget = settings_.learn && settings_.target == LearningTarget::TdStep;
  f.learns = settings_.learn;
  return f;
}

void QGuide::noteLightMotion(float share) {
  tables_.forget(share * settings_.forgetOnLightMove);
  tables_.forgetNee(share * shared::kNeeHalvingsPerRadius);
  if (points_ && (tables_.pendingHalvings() >= 1.0f || tables_.pendingNeeHalvings() >= 1.0f))
    tables_.ageNow(points_->slotEnd(), settings_);
}

void QGuide::recordLearning(gpu::PassRecorder& rec) {
  if (!settings_.learn) return;  // frozen: no targets were recorded, the tables stand
  tables_.recordLearning(rec, points_->slotEnd(), settings_);
}

uint64_t QGuide::memoryBytes() const {
  return points_->memoryBytes() + tables_.memoryBytes() + generator_.memoryBytes() +
         uniforms_.size();
}

GuidingStats QGuide::stats() const {
  GuidingStats s;
  s.points = points_->count();
  s.strata = settings_.strata();
  s.lightsLearned = tables_.lights();
  s.rejectionMin = radii_.rejectionMin;
  s.rejectionMax = radii_.rejectionMax;
  s.searchRadius = radii_.searchRadius;
  s.spawnedPoints = spawned_;
  return s;
}

}  // namespace qlight::guiding
