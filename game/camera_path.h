// A camera path: timed camera poses in a JSON file, recorded in the demo window (F9) and
// played by the window or the headless demo (--camera-path). The file:
//   {"keys": [{"time": 0, "position": [x, y, z], "forward": [x, y, z], "up": [x, y, z],
//              "yfov": 0.8}, ...]}
// times in seconds, strictly increasing, at least 2 keys; yfov (radians) on every key or on none.
#pragma once
#include <filesystem>
#include <optional>
#include <vector>

#include "engine/render/scene_draw.h"

namespace qlight::game {

struct CameraKey {
  float time = 0.0f;
  render::CameraView view;  // forward and up unit length and orthogonal
};

struct CameraPath {
  std::vector<CameraKey> keys;
  bool hasFov = true;  // false: the file gave no yfov (setFov gives the scene camera's)

  float start() const { return keys.front().time; }
  float end() const { return keys.back().time; }
  float duration() const { return end() - start(); }
  // The pose at `seconds`: position linear, orientation slerped between the two keys around
  // it, yfov linear; the first or last key outside the path's times.
  render::CameraView sample(float seconds) const;
  void setFov(float yfov);  // every key's
};

// `view` with forward made unit length and up the unit vector orthogonal to it in the plane
// of the two (a key's form); nullopt when forward is zero or up is zero or parallel to it.
std::optional<render::CameraView> orthonormal(const render::CameraView& view);

// Throws std::runtime_error "FILE: problem" (one line) when the file cannot be read, is not
// JSON, or has a missing or non-finite number, a zero or parallel forward/up, fewer than 2
// keys or times that do not increase.
CameraPath loadCameraPath(const std::filesystem::path& file);

// Writes through a temporary file and a rename, so a reader never sees half a path; creates
// the folder. Throws std::runtime_error naming the file when it cannot be written.
void saveCameraPath(const std::filesystem::path& file, const CameraPath& path);

}  // namespace qlight::game
