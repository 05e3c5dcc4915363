// The demo window's camera paths: F9 records the camera the window renders, a key a frame,
// into the --record-path file; --camera-path plays a path when the window opens, then the
// free camera takes over. Plain state, no window: the window feeds it each frame's view and
// step, which keeps the hook small and the logic testable.
#pragma once
#include <optional>
#include <string>

#include "game/camera_path.h"
#include "game/demo_window.h"

namespace qlight::game {

class WindowCameraPath {
 public:
  // `sceneYfov`: the field of view of a played path whose file gives none.
  WindowCameraPath(const DemoArgs& args, float sceneYfov);

  // While a path plays: the view `step` seconds further along (the first call: its first
  // key); nullopt once it has ended.
  std::optional<render::CameraView> play(float step);
  // F9: starts a recording, or stops it and writes the file (a message either way).
  void toggleRecording();
  // Every frame: the view rendered, `step` seconds after the previous frame's.
  void record(const render::CameraView& view, float step);
  // The window closes: a recording in progress is written.
  void finish();

  bool recording() const { return recording_; }
  size_t recordedKeys() const { return recorded_.keys.size(); }
  // The panel's Camera line: "recording (N keys)", the path playing, or the last result.
  std::string status() const;

 private:
  void say(std::string message);  // printed, and the panel's line until the next

  std::optional<CameraPath> playback_;
  std::string playbackFile_;
  float played_ = 0.0f;  // seconds along playback_
  std::string recordFile_;
  bool recording_ = false;
  CameraPath recorded_;
  std::string message_ = "F9 records a camera path";
};

}  // namespace qlight::game
