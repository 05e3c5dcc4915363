#include "engine/session/render_stats.h"

#include <algorithm>

namespace qlight::session {

double FrameResult::emitterHitShare() const {
  return double(counters.emitterHits) / double(std::max<uint64_t>(counters.paths, 1));
}

double FrameResult::meanPathLength() const {
  return double(counters.pathVertices) / double(std::max<uint64_t>(counters.paths, 1));
}

void RenderStats::add(const FrameResult& frame) {
  emitterHitShareByFrame.push_back(frame.emitterHitShare());
  pathLengthByFrame.push_back(frame.meanPathLength());
  counters += frame.counters;
  for (auto& [name, ms] : frame.gpuMs) gpuMs[name] += ms;
  spp += frame.samples;
  ++frames;
}

}  // namespace qlight::session
