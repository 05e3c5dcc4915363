// Reads the demo window's keyboard and mouse each frame (GLFW polling) into
// camera controls and one-shot actions. Keys act once per press; mouse look
// needs a drag that started outside ImGui's windows.
#pragma once
#include "game/window_camera.h"

struct GLFWwindow;

namespace qlight::game {

struct WindowActions {
  bool resetCamera = false;  // R
  bool togglePause = false;  // Space
  bool toggleUi = false;     // F1
  bool screenshot = false;   // F12
  bool recordPath = false;   // F9: start / stop recording the camera path
  bool quit = false;         // Esc
};

struct FrameInput {
  CameraControls camera;
  WindowActions actions;
};

class InputReader {
 public:
  explicit InputReader(GLFWwindow* window) : window_(window) {}
  // `wheel`: this frame's scroll steps (ImGui collects them from GLFW).
  FrameInput read(bool uiWantsMouse, bool uiWantsKeyboard, float wheel);

 private:
  bool pressedOnce(int key, bool enabled);

  GLFWwindow* window_;
  bool wasDown_[512] = {};
  bool dragging_ = false;
  double lastX_ = 0, lastY_ = 0;
};

}  // namespace qlight::game
