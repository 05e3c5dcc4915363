// Dynamic resolution for the demo window: while the camera moves, the render
// size follows a target frame time (cost ~ pixels ~ scale^2); once the camera
// has been still for a few frames the full render scale comes back and the
// image accumulates there. Plain data and one update per frame, so tests can
// drive it with synthetic frame times.
#pragma once
#include <cstdint>

namespace qlight::game {

struct DynamicResolution {
  // Frames the camera must stay still before the full scale returns: one frame
  // of pause between two key presses must not flip the size back and forth.
  static constexpr uint32_t kSettleFrames = 4;
  // The smallest scale it goes down to, as a share of the full render scale.
  static constexpr float kMinShare = 0.2f;
  // Changes smaller than this (relative) are not made: each size change reallocates
  // the tracer's images.
  static constexpr float kDeadband = 0.08f;

  bool enabled = true;
  float targetMs = 100.0f;  // the frame time to hold while moving
  float scale = 1.0f;       // the current render scale (of the window size)
  uint32_t stillFrames = kSettleFrames;

  // After a frame that took `frameMs` at the current scale; `moving`: the camera
  // moved since the previous frame; `fullScale`: the user's render scale. Returns
  // the scale for the next frame.
  float update(float fullScale, double frameMs, bool moving);
  bool lowered(float fullScale) const { return scale < fullScale; }
};

}  // namespace qlight::game
