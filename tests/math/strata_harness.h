// Includes strata.h with QL_CDF_AT / QL_Q_AT reading C++ vectors, the way a
// shader reads storage buffers. Every test includes strata.h through this
// header so the inline functions are defined identically in each file.
#pragma once

#include <vector>

namespace qlight::test {
inline std::vector<float> gCdfBuffer;
inline std::vector<float> gQBuffer;
}  // namespace qlight::test

#define QL_CDF_AT(i) (::qlight::test::gCdfBuffer.at(i))
#define QL_Q_AT(i) (::qlight::test::gQBuffer.at(i))
#include "shaders/shared/strata.h"

namespace qlight::test {

// Writes the inclusive CDF of Q_k cosInt_k for one cache point at `base`, the
// job of the CDF pass.
inline void writeGuidedCdf(const std::vector<float>& q, uint32_t base, uint32_t rows,
                           uint32_t cols) {
  if (gCdfBuffer.size() < base + q.size()) gCdfBuffer.resize(base + q.size());
  double running = 0.0;
  for (uint32_t k = 0; k < q.size(); ++k) {
    running += qlight::shared::guidedStratumWeight(q[k], k, rows, cols);
    gCdfBuffer[base + k] = float(running);
  }
}

}  // namespace qlight::test
