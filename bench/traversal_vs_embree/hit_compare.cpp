#include "bench/traversal_vs_embree/hit_compare.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace qlight::bench {

Agreement compareHits(std::span<const shared::TraceHit> qlight,
                      std::span<const shared::TraceHit> embree, bool anyHit, float sceneSize,
                      float relativeTolerance) {
  if (qlight.size() != embree.size()) throw std::logic_error("hit lists differ in length");
  constexpr size_t kExamples = 8;
  const double tolerance = double(relativeTolerance) * sceneSize;
  Agreement a;
  a.rays = qlight.size();
  for (size_t i = 0; i < qlight.size(); ++i) {
    const shared::TraceHit& q = qlight[i];
    const shared::TraceHit& e = embree[i];
    a.qlightHits += q.hit != 0;
    a.embreeHits += e.hit != 0;
    bool mismatch = false;
    if ((q.hit != 0) != (e.hit != 0)) {
      ++a.hitMissDiffer;
      mismatch = true;
    } else if (q.hit && !anyHit) {  // an any-hit query reports no t worth comparing
      double d = std::abs(double(q.t) - double(e.t));
      a.maxDistanceDifference = std::max(a.maxDistanceDifference, d / sceneSize);
      if (!(d <= tolerance)) {
        ++a.distanceDiffer;
        mismatch = true;
      } else if (q.instance != e.instance || q.primitive != e.primitive) {
        ++a.otherTriangle;
      }
    }
    if (mismatch && a.examples.size() < kExamples) a.examples.push_back(uint32_t(i));
  }
  return a;
}

}  // namespace qlight::bench
