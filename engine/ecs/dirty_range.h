// The span of dense slots changed since an uploader last copied a component array to the GPU.
// One contiguous [begin, end) range keeps the upload a single copy; it may cover unchanged
// slots in between, never miss a changed one.
#pragma once

#include <algorithm>
#include <cstddef>

namespace qlight::ecs {

struct DirtyRange {
  size_t begin = 0;
  size_t end = 0;  // exclusive; begin == end means clean

  bool empty() const { return begin >= end; }
  size_t size() const { return empty() ? 0 : end - begin; }
  bool covers(size_t i) const { return i >= begin && i < end; }

  void include(size_t i) {
    if (empty()) {
      begin = i;
      end = i + 1;
    } else {
      begin = std::min(begin, i);
      end = std::max(end, i + 1);
    }
  }
  void include(DirtyRange r) {
    if (r.empty()) return;
    include(r.begin);
    include(r.end - 1);
  }
  // Slots at or past n no longer exist after the array shrank.
  void clampTo(size_t n) {
    end = std::min(end, n);
    if (empty()) *this = {};
  }
  friend bool operator==(DirtyRange, DirtyRange) = default;
};

}  // namespace qlight::ecs
