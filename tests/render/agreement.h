// Comparing two unbiased estimators of one image within their noise: each is
// rendered K times with independent seeds; per region and channel, Welch's t
// of the two sets of region means must stay below a bound chosen for the
// number of comparisons (false alarm rate below ~1e-3 for the whole test).
#pragma once
#include <cstdio>
#include <functional>

#include "tests/render/render_support.h"

namespace qlight::test {

struct AgreementSetup {
  uint32_t size = 40;     // square image
  uint32_t blocks = 4;    // blocks x blocks regions compared separately
  uint32_t batches = 16;  // independent renders per estimator
};

// [region * 3 + channel][batch]
using RegionSamples = std::vector<std::vector<double>>;

// render(seed) returns one independent render.
inline RegionSamples regionMeans(const AgreementSetup& a,
                                 const std::function<image::LinearImage(uint32_t)>& render,
                                 uint32_t seedBase) {
  RegionSamples out(a.blocks * a.blocks * 3);
  uint32_t step = a.size / a.blocks;
  for (uint32_t b = 0; b < a.batches; ++b) {
    image::LinearImage img = render(seedBase + b);
    for (uint32_t by = 0; by < a.blocks; ++by)
      for (uint32_t bx = 0; bx < a.blocks; ++bx)
        for (int c = 0; c < 3; ++c)
          out[(by * a.blocks + bx) * 3 + c].push_back(
              regionMean(img, bx * step, by * step, (bx + 1) * step, (by + 1) * step, c));
  }
  return out;
}

// With 16 batches Welch's t is near Student-t with ~15+ degrees of freedom;
// its two-sided tail at 6 is ~1e-5, so up to ~150 comparisons keep the
// family-wise false alarm rate near 1e-3, while a real bias of a few
// standard errors anywhere is caught.
constexpr double kMaxWelchT = 6.0;

inline double expectAgree(const RegionSamples& a, const RegionSamples& b, const char* what) {
  double worst = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    Moments ma = moments(a[i]), mb = moments(b[i]);
    double se = std::sqrt(ma.variance / ma.n + mb.variance / mb.n);
    if (se == 0) {
      EXPECT_DOUBLE_EQ(ma.mean, mb.mean) << what << " region " << i / 3;
      continue;
    }
    double t = std::abs(ma.mean - mb.mean) / se;
    worst = std::max(worst, t);
    EXPECT_LT(t, kMaxWelchT) << what << ": region " << i / 3 << " channel " << i % 3 << " means "
                             << ma.mean << " vs " << mb.mean << " (standard error " << se << ")";
  }
  std::printf("%s: worst |t| = %.2f over %zu comparisons\n", what, worst, a.size());
  return worst;
}

// The whole-image mean of one estimator over its batches.
inline Moments imageMeans(const RegionSamples& s) {
  std::vector<double> whole(s.front().size(), 0.0);
  for (size_t i = 0; i < s.size(); i += 3)
    for (size_t b = 0; b < whole.size(); ++b) whole[b] += s[i][b] / double(s.size() / 3);
  return moments(whole);
}

}  // namespace qlight::test
