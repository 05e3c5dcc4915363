// Maps an entity's slot index to its position in a dense array. Paged, so a storage of a few
// components on entities with large indices costs a page, not a slot per entity ever made.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

namespace qlight::ecs {

class SparseIndex {
 public:
  static constexpr uint32_t kAbsent = std::numeric_limits<uint32_t>::max();
  static constexpr uint32_t kPageBits = 12;
  static constexpr uint32_t kPageSize = 1u << kPageBits;

  uint32_t find(uint32_t index) const {
    const size_t page = index >> kPageBits;
    if (page >= pages_.size() || !pages_[page]) return kAbsent;
    return pages_[page][index & (kPageSize - 1)];
  }

  void set(uint32_t index, uint32_t position) {
    const size_t page = index >> kPageBits;
    if (page >= pages_.size()) pages_.resize(page + 1);
    if (!pages_[page]) {
      pages_[page] = std::make_unique<uint32_t[]>(kPageSize);
      std::fill_n(pages_[page].get(), kPageSize, kAbsent);
    }
    pages_[page][index & (kPageSize - 1)] = position;
  }

  void erase(uint32_t index) {
    const size_t page = index >> kPageBits;
    if (page < pages_.size() && pages_[page]) pages_[page][index & (kPageSize - 1)] = kAbsent;
  }

 private:
  std::vector<std::unique_ptr<uint32_t[]>> pages_;
};

}  // namespace qlight::ecs
