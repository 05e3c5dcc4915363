#include "engine/gpu/prefix_sum.h"

#include <stdexcept>

#include "shaders/shared/prefix_sum.h"
#include "shaders/shared/strata.h"

namespace qlight::gpu {

using shared::kScanTileElements;
using shared::PrefixSumPush;

// A segment must fit one tile (no carry crosses tiles), and a cache point's
// strata are one segment of the Q CDF scan.
static_assert(PrefixSum::kMaxSegmentLength <= kScanTileElements, "a segment must fit a scan tile");
static_assert(PrefixSum::kMaxSegmentLength >= shared::kMaxStrata,
              "a point's strata must fit one segment");

PrefixSum::PrefixSum(const Context& ctx)
    : ctx_(ctx), tilesPipeline_(ctx, "prefix_sum_tiles"), addPipeline_(ctx, "prefix_sum_add") {}

const Buffer& PrefixSum::tileSums(uint32_t level, uint32_t tiles) {
  if (levels_.size() <= level) levels_.resize(level + 1);
  auto& slot = levels_[level];
  VkDeviceSize bytes = VkDeviceSize(tiles) * sizeof(float);
  if (!slot || slot->size() < bytes) {
    if (slot) retired_.push_back(std::move(slot));
    slot = std::make_unique<Buffer>(ctx_, bytes, "prefix_sum.tiles" + std::to_string(level));
  }
  return *slot;
}

void PrefixSum::scanLevel(PassRecorder& recorder, const Buffer& data, uint32_t count,
                          uint32_t level) {
  if (count == 0) return;
  uint32_t tiles = (count + kScanTileElements - 1) / kScanTileElements;
  const Buffer& sums = tileSums(level, tiles);
  PrefixSumPush push{count, 0, kScanTileElements, 0};
  recorder.pass("prefix_sum.tiles", tilesPipeline_)
      .write(QL_SCAN_BIND_VALUES, data)
      .write(QL_SCAN_BIND_TILE_SUMS, sums)
      .push(push)
      .dispatch(tiles);
  if (tiles == 1) return;
  scanLevel(recorder, sums, tiles, level + 1);
  recorder.pass("prefix_sum.add", addPipeline_)
      .write(QL_SCAN_BIND_VALUES, data)
      .read(QL_SCAN_BIND_TILE_SUMS, sums)
      .push(push)
      .dispatchThreads(count);
}

void PrefixSum::scan(PassRecorder& recorder, const Buffer& data, uint32_t count) {
  if (VkDeviceSize(count) * sizeof(float) > data.size())
    throw std::invalid_argument("prefix sum of " + std::to_string(count) +
                                " floats exceeds buffer " + data.name());
  scanLevel(recorder, data, count, 0);
}

void PrefixSum::scanSegments(PassRecorder& recorder, const Buffer& data, uint32_t segmentCount,
                             uint32_t segmentLength) {
  if (segmentLength == 0 || segmentLength > kMaxSegmentLength)
    throw std::invalid_argument("segment length must be 1.." + std::to_string(kMaxSegmentLength));
  uint64_t count = uint64_t(segmentCount) * segmentLength;
  if (count * sizeof(float) > data.size() || count > UINT32_MAX)
    throw std::invalid_argument("segmented prefix sum exceeds buffer " + data.name());
  if (count == 0) return;
  // Each tile holds whole segments, so no carry crosses tiles.
  uint32_t segmentsPerTile = kScanTileElements / segmentLength;
  uint32_t tileElements = segmentsPerTile * segmentLength;
  uint32_t tiles = (segmentCount + segmentsPerTile - 1) / segmentsPerTile;
  const Buffer& sums = tileSums(0, tiles);
  PrefixSumPush push{uint32_t(count), segmentLength, tileElements, 0};
  recorder.pass("prefix_sum.segments", tilesPipeline_)
      .write(QL_SCAN_BIND_VALUES, data)
      .write(QL_SCAN_BIND_TILE_SUMS, sums)
      .push(push)
      .dispatch(tiles);
}

}  // namespace qlight::gpu
