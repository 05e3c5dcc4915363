#include "game/window_camera_path.h"

#include <algorithm>
#include <cstdio>
#include <exception>

namespace qlight::game {

WindowCameraPath::WindowCameraPath(const DemoArgs& args, float sceneYfov)
    : playbackFile_(args.cameraPathFile), recordFile_(args.recordPath) {
  if (args.cameraPathFile.empty()) return;
  playback_ = args.cameraPath;
  if (!playback_->hasFov) playback_->setFov(sceneYfov);
  char line[64];
  std::snprintf(line, sizeof(line), " (%.2f s, %zu keys)", playback_->duration(),
                playback_->keys.size());
  say("playing camera path " + playbackFile_ + line);
}

std::optional<render::CameraView> WindowCameraPath::play(float step) {
  if (!playback_) return std::nullopt;
  const float at = played_;
  played_ += step;
  const render::CameraView view = playback_->sample(playback_->start() + at);
  if (at >= playback_->duration()) {  // this frame shows the last key; then the free camera
    playback_.reset();
    say("camera path " + playbackFile_ + " played; the free camera takes over");
  }
  return view;
}

void WindowCameraPath::toggleRecording() {
  if (!recording_) {
    recording_ = true;
    recorded_ = CameraPath{};
    say("recording the camera (F9 stops)");
    return;
  }
  recording_ = false;
  const size_t keys = recorded_.keys.size();
  if (keys < 2) {
    say("recording stopped after " + std::to_string(keys) +
        " key; nothing written (a path needs 2)");
    return;
  }
  try {
    saveCameraPath(recordFile_, recorded_);
    char line[96];
    std::snprintf(line, sizeof(line), "recorded %zu keys (%.2f s) into ", keys,
                  recorded_.duration());
    say(line + recordFile_);
  } catch (const std::exception& e) {
    say(std::string("camera path not recorded: ") + e.what());  // the window goes on
  }
}

void WindowCameraPath::record(const render::CameraView& view, float step) {
  if (!recording_) return;
  const std::optional<render::CameraView> pose = orthonormal(view);
  if (!pose) return;  // the free camera never gives one, but a file must load again
  std::vector<CameraKey>& keys = recorded_.keys;
  // A frame without time between (a coarse clock) replaces the last key: times must increase.
  if (!keys.empty() && step <= 1e-6f) {
    keys.back().view = *pose;
    return;
  }
  keys.push_back({keys.empty() ? 0.0f : keys.back().time + step, *pose});
}

void WindowCameraPath::finish() {
  if (recording_) toggleRecording();
}

std::string WindowCameraPath::status() const {
  if (recording_) return "recording (" + std::to_string(recorded_.keys.size()) + " keys)";
  if (playback_) {
    char line[64];
    std::snprintf(line, sizeof(line), "playing %.1f / %.1f s",
                  std::min(played_, playback_->duration()), playback_->duration());
    return line;
  }
  return message_;
}

void WindowCameraPath::say(std::string message) {
  std::printf("qlight demo: %s\n", message.c_str());
  message_ = std::move(message);
}

}  // namespace qlight::game
