// The cache points as the shaders see them: every CachePoint entity keeps a
// stable slot (its row in the learned tables and its index in the GPU point
// array) for its lifetime, so destroying one point never moves another's
// learned row (the ECS storage is swap-and-pop: dense indices move). The set
// uploads the points that changed and rebuilds the hashed grid they are
// searched by.
#pragma once
#include <memory>
#include <vector>

#include "engine/ecs/registry.h"
#include "engine/gpu/buffer.h"
#include "engine/guiding/point_grid.h"

namespace qlight::guiding {

class CachePointSet {
 public:
  // `budget` slots; the grid's cells are twice the search radius (2x2x2 cells cover it).
  CachePointSet(const gpu::Context& ctx, uint32_t budget, float searchRadius);

  // Creates a CachePoint entity in the lowest free slot. False when every slot is taken.
  bool add(ecs::Registry& registry, CachePoint point);
  // Destroys every CachePoint entity; all slots become free.
  void clear(ecs::Registry& registry);
  // Frees the slots of points destroyed since the last sync, uploads the points added or
  // changed, and rebuilds the grid when anything changed.
  struct SyncResult {
    bool changed = false;
    // Slots freed by destroyed points and taken again since: their learned rows need a reset.
    std::vector<uint32_t> reusedSlots;
  };
  SyncResult sync(ecs::Registry& registry);

  uint32_t count() const { return live_; }   // live points
  uint32_t slotEnd() const { return top_; }  // slots below this may be in use
  uint32_t budget() const { return uint32_t(used_.size()); }
  float searchRadius() const { return searchRadius_; }
  const PointGrid& grid() const { return grid_; }

  uint64_t memoryBytes() const;  // GPU buffers
  const gpu::BufferView& pointsView() const { return *pointsView_; }
  const gpu::BufferView& gridBucketsView() const { return *bucketsView_; }
  const gpu::BufferView& gridPointsView() const { return *gridPointsView_; }

 private:
  uint32_t takeSlot();
  void freeDestroyed(ecs::Registry& registry);
  void uploadChanged(ecs::Registry& registry);
  void uploadGrid(ecs::Registry& registry);

  const gpu::Context& ctx_;
  float searchRadius_;
  std::vector<uint8_t> used_;        // per slot
  std::vector<uint8_t> everUsed_;    // per slot: its table row has learned something
  std::vector<uint32_t> freeSlots_;  // freed slots below top_, highest first
  std::vector<uint32_t> reused_;     // freed slots taken again since the last sync
  uint32_t top_ = 0;                 // slots at or above this were never used
  uint32_t live_ = 0;
  bool gridStale_ = true;
  PointGrid grid_;
  std::unique_ptr<gpu::Buffer> points_, buckets_, gridPoints_;
  std::unique_ptr<gpu::BufferView> pointsView_, bucketsView_, gridPointsView_;
};

}  // namespace qlight::guiding
