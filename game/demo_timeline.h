// The headless demo's frames: when each is, where its camera is and which are written.
// The camera is the sway flythrough around the scene's camera (--frames frames), the scene's
// own, possibly animated camera (--camera gltf), or a camera path file (--camera-path: the
// path's whole duration at --fps, every frame written, so they make a video).
#pragma once
#include <optional>

#include "engine/render/scene_draw.h"
#include "game/demo_window.h"
#include "game/flythrough.h"

namespace qlight::game {

// Frames that cover `path` at `fps`, both ends included. Throws std::runtime_error naming
// `file` when that is more than the demo renders (--frames' limit).
uint32_t framesAlong(const CameraPath& path, float fps, const std::string& file);

class DemoTimeline {
 public:
  // `args.frames` already holds framesAlong for a path.
  DemoTimeline(const DemoArgs& args, const render::CameraView& sceneCamera, float sceneRadius);

  uint32_t frames() const { return frames_; }
  float time(uint32_t frame) const;  // scene seconds
  // The frame's camera; nullopt: the scene's own at that time.
  std::optional<render::CameraView> camera(float seconds) const;
  bool written(uint32_t frame) const;  // as frame_NNNN.png
  bool everyFrameWritten() const { return saveEvery_ == 1; }
  const char* name() const;  // "sway", "gltf" or "path", for stats.json

 private:
  std::optional<CameraPath> path_;  // with the scene camera's yfov where the file has none
  bool sceneCamera_ = false;
  Flythrough sway_;
  uint32_t frames_;
  float fps_;
  uint32_t saveEvery_;
};

}  // namespace qlight::game
