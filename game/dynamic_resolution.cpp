#include "game/dynamic_resolution.h"

#include <algorithm>
#include <cmath>

namespace qlight::game {

float DynamicResolution::update(float fullScale, double frameMs, bool moving) {
  stillFrames = moving ? 0 : std::min(stillFrames + 1, kSettleFrames);
  if (!enabled || stillFrames >= kSettleFrames || !(targetMs > 0.0f)) {
    scale = fullScale;
    return scale;
  }
  if (!(frameMs > 0.0) || !std::isfinite(frameMs)) return scale;
  const float lowest = kMinShare * fullScale;
  // Cost follows the pixel count: the scale that would have met the target. Half of the
  // way there (in log) each frame damps the noise of single frame times.
  const float ideal = scale * std::sqrt(float(targetMs / frameMs));
  if (std::abs(ideal - scale) > kDeadband * scale) scale = std::sqrt(scale * ideal);
  scale = std::clamp(scale, lowest, fullScale);
  return scale;
}

}  // namespace qlight::game
