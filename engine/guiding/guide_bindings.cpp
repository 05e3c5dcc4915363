#include "engine/guiding/guide_bindings.h"

#include "shaders/shared/guiding_types.h"

namespace qlight::guiding {

void bindGuideBuffers(gpu::PassBuilder& pass, const GuideBuffers& b) {
  pass.read(QL_BIND_GUIDING, *b.uniforms)
      .read(QL_BIND_CACHE_POINTS, *b.points)
      .read(QL_BIND_GRID_BUCKETS, *b.gridBuckets)
      .read(QL_BIND_GRID_POINTS, *b.gridPoints)
      .read(QL_BIND_Q_CDF, *b.qCdf)
      .read(QL_BIND_Q_CHILDREN, *b.qChildren)
      .write(QL_BIND_Q_SUM, *b.qSums)
      .write(QL_BIND_Q_COUNT, *b.qCounts)
      .write(QL_BIND_SPAWN, *b.spawnReports)
      .read(QL_BIND_V_CDF, *b.vCdf)
      .write(QL_BIND_V_SUM, *b.vSums)
      .write(QL_BIND_V_COUNT, *b.vCounts)
      .read(QL_BIND_POINT_UPDATES, *b.pointUpdates);
}

}  // namespace qlight::guiding
