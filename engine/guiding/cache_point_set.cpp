#include "engine/guiding/cache_point_set.h"

#include <algorithm>

namespace qlight::guiding {
namespace {

uint32_t nextPowerOfTwo(uint32_t v) {
  uint32_t p = 1;
  while (p < v) p <<= 1;
  return p;
}

}  // namespace

CachePointSet::CachePointSet(const gpu::Context& ctx, uint32_t budget, float searchRadius)
    : ctx_(ctx), searchRadius_(searchRadius), used_(budget, 0), everUsed_(budget, 0) {
  grid_.cellSize = searchRadius > 0.0f ? searchRadius : 1.0f;  // no points yet: any
  grid_.hashSize = nextPowerOfTwo(std::max<uint32_t>(2 * budget, 1024));
  grid_.buckets.assign(grid_.hashSize + 1, 0);
  points_ = std::make_unique<gpu::Buffer>(
      ctx, std::max<uint64_t>(uint64_t(budget) * sizeof(CachePoint), 16), "guiding.points",
      gpu::kTexelTableUsage);
  buckets_ = std::make_unique<gpu::Buffer>(ctx, (grid_.hashSize + 1ull) * 4, "guiding.gridBuckets",
                                           gpu::kTexelTableUsage);
  gridPoints_ = std::make_unique<gpu::Buffer>(ctx, std::max<uint64_t>(uint64_t(budget) * 4, 16),
                                              "guiding.gridPoints", gpu::kTexelTableUsage);
  pointsView_ = std::make_unique<gpu::BufferView>(ctx, *points_, VK_FORMAT_R32G32B32A32_SFLOAT);
  bucketsView_ = std::make_unique<gpu::BufferView>(ctx, *buckets_, VK_FORMAT_R32_UINT);
  gridPointsView_ = std::make_unique<gpu::BufferView>(ctx, *gridPoints_, VK_FORMAT_R32_UINT);
  buckets_->upload(ctx, grid_.buckets.data(), grid_.buckets.size() * 4);
}

uint64_t CachePointSet::memoryBytes() const {
  return points_->size() + buckets_->size() + gridPoints_->size();
}

uint32_t CachePointSet::takeSlot() {
  if (!freeSlots_.empty()) {
    uint32_t slot = freeSlots_.back();  // the lowest: the list is kept highest first
    freeSlots_.pop_back();
    if (everUsed_[slot]) reused_.push_back(slot);
    return slot;
  }
  return top_++;
}

bool CachePointSet::add(ecs::Registry& registry, CachePoint point) {
  freeDestroyed(registry);
  if (live_ >= budget()) return false;
  point.slot = takeSlot();
  used_[point.slot] = 1;
  everUsed_[point.slot] = 1;
  ++live_;
  registry.emplace<CachePoint>(registry.create(), point);
  gridStale_ = true;
  return true;
}

void CachePointSet::clear(ecs::Registry& registry) {
  std::vector<ecs::Entity> all;
  registry.view<const CachePoint>().each(
      [&](ecs::Entity e, const CachePoint&) { all.push_back(e); });
  for (ecs::Entity e : all) registry.destroy(e);
  std::fill(used_.begin(), used_.end(), 0);
  std::fill(everUsed_.begin(), everUsed_.end(), 0);  // the tables are reset with the points
  freeSlots_.clear();
  reused_.clear();
  top_ = live_ = 0;
  gridStale_ = true;
}

void CachePointSet::freeDestroyed(ecs::Registry& registry) {
  const auto& storage = registry.storage<CachePoint>();
  if (storage.size() == live_) return;  // points join only through add()
  std::vector<uint8_t> alive(budget(), 0);
  for (const CachePoint& p : storage.values()) alive[p.slot] = 1;
  for (uint32_t s = 0; s < top_; ++s)
    if (used_[s] && !alive[s]) {
      used_[s] = 0;
      freeSlots_.push_back(s);
    }
  std::sort(freeSlots_.begin(), freeSlots_.end(), std::greater<>());
  live_ = uint32_t(storage.size());
  gridStale_ = true;
}

CachePointSet::SyncResult CachePointSet::sync(ecs::Registry& registry) {
  freeDestroyed(registry);
  uploadChanged(registry);
  SyncResult result;
  result.changed = gridStale_;  // set by every added, destroyed or changed point
  if (gridStale_) uploadGrid(registry);
  gridStale_ = false;
  result.reusedSlots = std::exchange(reused_, {});
  return result;
}

void CachePointSet::uploadChanged(ecs::Registry& registry) {
  auto& storage = registry.storage<CachePoint>();
  ecs::DirtyRange dirty = storage.dirtyRange();
  dirty.clampTo(storage.size());
  // Each changed point goes to its slot; runs of consecutive slots are one copy (with no
  // point ever destroyed, slots follow the dense order: one copy).
  const CachePoint* values = storage.data();
  size_t i = dirty.begin;
  while (i < dirty.end) {
    size_t j = i + 1;
    while (j < dirty.end && values[j].slot == values[j - 1].slot + 1) ++j;
    points_->upload(ctx_, values + i, (j - i) * sizeof(CachePoint),
                    uint64_t(values[i].slot) * sizeof(CachePoint));
    i = j;
  }
  if (!dirty.empty()) gridStale_ = true;
  storage.clearDirty();
}

void CachePointSet::uploadGrid(ecs::Registry& registry) {
  const auto& storage = registry.storage<CachePoint>();
  std::vector<uint32_t> slots;
  slots.reserve(storage.size());
  for (const CachePoint& p : storage.values()) slots.push_back(p.slot);
  grid_ = buildPointGrid(storage.values(), grid_.cellSize, grid_.hashSize, slots);
  buckets_->upload(ctx_, grid_.buckets.data(), grid_.buckets.size() * 4);
  if (grid_.points.size() * 4 > gridPoints_->size()) {  // points are listed in several cells
    gridPointsView_.reset();
    gridPoints_ = std::make_unique<gpu::Buffer>(ctx_, grid_.points.size() * 4 * 5 / 4,
                                                "guiding.gridPoints", gpu::kTexelTableUsage);
    gridPointsView_ = std::make_unique<gpu::BufferView>(ctx_, *gridPoints_, VK_FORMAT_R32_UINT);
  }
  if (!grid_.points.empty())
    gridPoints_->upload(ctx_, grid_.points.data(), grid_.points.size() * 4);
}

}  // namespace qlight::guiding
