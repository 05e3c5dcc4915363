// The demo window's free camera: position plus yaw/pitch about world +Y (glTF
// is Y-up), moved by WASD/QE and turned by mouse drags.
#pragma once
#include <glm/glm.hpp>

#include "engine/render/scene_draw.h"

namespace qlight::game {

// What the controls ask of the camera this frame.
struct CameraControls {
  bool forward = false, back = false, left = false, right = false, down = false, up = false;
  bool fast = false;           // Shift: kFastFactor times the speed
  glm::vec2 lookPixels{0.0f};  // mouse motion while dragging (x right, y down)
  float wheel = 0.0f;          // scroll steps: each scales the speed by kWheelStep
};

class FreeCamera {
 public:
  static constexpr float kFastFactor = 4.0f;
  static constexpr float kWheelStep = 1.2f;
  static constexpr float kRadiansPerPixel = 0.004f;

  // Starts at `view`, moving `speed` world units per second.
  void reset(const render::CameraView& view, float speed);
  void update(const CameraControls& controls, float dtSeconds);
  render::CameraView view() const;

  glm::vec3 position{0.0f};
  float yaw = 0.0f;    // radians about +Y; 0 looks down -Z
  float pitch = 0.0f;  // radians above the horizon
  float speed = 1.0f;  // world units per second
  float yfov = 0.8f;

 private:
  glm::vec3 forward() const;
};

}  // namespace qlight::game
