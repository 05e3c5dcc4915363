#include "game/demo_timeline.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace qlight::game {

uint32_t framesAlong(const CameraPath& path, float fps, const std::string& file) {
  // A small allowance so a path of exactly N frames' length gets its last key.
  const double frames = std::floor(double(path.duration()) * fps + 1e-3) + 1.0;
  if (frames > double(kMaxDemoFrames))
    throw std::runtime_error(file + ": " + std::to_string(path.duration()) + " s at " +
                             std::to_string(fps) + " fps is more than " +
                             std::to_string(kMaxDemoFrames) + " frames (lower --fps)");
  return uint32_t(frames);
}

DemoTimeline::DemoTimeline(const DemoArgs& args, const render::CameraView& sceneCamera,
                           float sceneRadius)
    : sceneCamera_(args.camera == "gltf"),
      sway_{sceneCamera, sceneRadius, args.moveSeconds},
      frames_(args.frames),
      fps_(args.fps),
      saveEvery_(args.cameraPathFile.empty() ? args.saveEvery : 1) {
  if (args.cameraPathFile.empty()) return;
  path_ = args.cameraPath;
  if (!path_->hasFov) path_->setFov(sceneCamera.yfov);
}

float DemoTimeline::time(uint32_t frame) const {
  const float t = float(frame) / fps_;
  return path_ ? std::min(path_->start() + t, path_->end()) : t;
}

std::optional<render::CameraView> DemoTimeline::camera(float seconds) const {
  if (path_) return path_->sample(seconds);
  if (sceneCamera_) return std::nullopt;
  return sway_.at(seconds);
}

bool DemoTimeline::written(uint32_t frame) const {
  return frame + 1 == frames_ || (saveEvery_ > 0 && frame % saveEvery_ == 0);
}

const char* DemoTimeline::name() const { return path_ ? "path" : sceneCamera_ ? "gltf" : "sway"; }

}  // namespace qlight::game
