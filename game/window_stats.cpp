#include "game/window_stats.h"

#include <algorithm>

namespace qlight::game {
namespace {
constexpr double kSmoothing = 0.1;  // weight of the newest frame: about ten frames of memory

void blend(double& average, double value, bool first) {
  average = first ? value : average + kSmoothing * (value - average);
}
}  // namespace

void FrameStats::add(const FrameSample& s) {
  const render::FrameCounters& c = s.counters;
  double paths = double(std::max<uint64_t>(c.paths, 1));
  blend(frameMs_, s.seconds * 1e3, first_);
  blend(mrays_, s.seconds > 0 ? double(c.rays) / s.seconds * 1e-6 : 0.0, first_);
  blend(emitterHitShare_, double(c.emitterHits) / paths, first_);
  blend(meanPathLength_, double(c.pathVertices) / paths, first_);
  rejectedSamples_ += c.invalidSamples;
  // Passes absent this frame (e.g. the accumulation clear) count as 0 ms.
  for (auto& [name, ms] : gpuMs_)
    if (!s.gpuMs.count(name)) blend(ms, 0.0, false);
  for (auto& [name, ms] : s.gpuMs) {
    auto it = gpuMs_.find(name);
    if (it == gpuMs_.end())
      gpuMs_[name] = ms;
    else
      blend(it->second, ms, false);
  }
  first_ = false;
}

double FrameStats::gpuTotalMs() const {
  double total = 0;
  for (auto& [name, ms] : gpuMs_) total += ms;
  return total;
}

}  // namespace qlight::game
