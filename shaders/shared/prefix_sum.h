// Parallel inclusive prefix sum over floats: tiles of kScanTileElements scanned
// per workgroup, tile totals scanned recursively, then added back.
#ifndef QLIGHT_SHARED_PREFIX_SUM_H
#define QLIGHT_SHARED_PREFIX_SUM_H
#include "common.h"

#define QL_SCAN_GROUP_SIZE 256
#define QL_SCAN_ITEMS_PER_THREAD 4

// Both passes (prefix_sum_tiles, prefix_sum_add): the scanned values, in
// place, and the tile totals (tiles writes them, add reads them back scanned).
#define QL_SCAN_BIND_VALUES 0
#define QL_SCAN_BIND_TILE_SUMS 1

QL_BEGIN
QL_CONST uint kScanTileElements = QL_SCAN_GROUP_SIZE * QL_SCAN_ITEMS_PER_THREAD;

struct PrefixSumPush {
  uint count;          // elements in the buffer
  uint segmentLength;  // 0: one scan over everything; else restart every segmentLength elements
  uint tileElements;   // elements per workgroup tile (a whole number of segments)
  uint pad;
};
QL_CHECK_SIZE(PrefixSumPush, 16);
QL_END

#endif
