// Frame statistics for the panel: smoothed over recent frames so the numbers
// are readable while they update every frame.
#pragma once
#include <map>
#include <string>

#include "engine/render/path_tracer.h"

namespace qlight::game {

struct FrameSample {
  double seconds = 0;  // wall time since the previous frame
  render::FrameCounters counters;
  std::map<std::string, double> gpuMs;  // per pass name
};

class FrameStats {
 public:
  void add(const FrameSample& sample);

  double frameMs() const { return frameMs_; }
  double fps() const { return frameMs_ > 0 ? 1e3 / frameMs_ : 0.0; }
  double mraysPerSecond() const { return mrays_; }
  double emitterHitShare() const { return emitterHitShare_; }
  double meanPathLength() const { return meanPathLength_; }
  // Samples whose radiance was NaN or infinite, dropped from the image, since the start.
  uint64_t rejectedSamples() const { return rejectedSamples_; }
  double gpuTotalMs() const;
  const std::map<std::string, double>& gpuMs() const { return gpuMs_; }

 private:
  bool first_ = true;
  double frameMs_ = 0, mrays_ = 0, emitterHitShare_ = 0, meanPathLength_ = 0;
  uint64_t rejectedSamples_ = 0;
  std::map<std::string, double> gpuMs_;
};

// "total T, pass ms, ..." of the smoothed GPU times, passes over 0.5 ms, the slowest first.
std::string passTimesLine(const FrameStats& stats);

}  // namespace qlight::game
