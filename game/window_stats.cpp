#include "game/window_stats.h"

#include <algorithm>
#include <cstdio>
#include <vector>

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

std::string passTimesLine(const FrameStats& stats) {
  std::vector<std::pair<std::string, double>> passes(stats.gpuMs().begin(), stats.gpuMs().end());
  std::sort(passes.begin(), passes.end(),
            [](const auto& a, const auto& b) { return a.second > b.second; });
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "total %.1f", stats.gpuTotalMs());
  std::string line = buffer;
  for (const auto& [name, ms] : passes) {
    if (ms < 0.5) break;
    std::snprintf(buffer, sizeof buffer, ", %s %.1f", name.c_str(), ms);
    line += buffer;
  }
  return line;
}

}  // namespace qlight::game
