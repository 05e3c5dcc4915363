#include "game/window_input.h"

#include <GLFW/glfw3.h>

namespace qlight::game {

bool InputReader::pressedOnce(int key, bool enabled) {
  bool down = glfwGetKey(window_, key) == GLFW_PRESS;
  bool edge = down && !wasDown_[key];
  wasDown_[key] = down;
  return enabled && edge;
}

FrameInput InputReader::read(bool uiWantsMouse, bool uiWantsKeyboard, float wheel) {
  FrameInput in;
  bool keys = !uiWantsKeyboard;
  auto held = [&](int key) { return keys && glfwGetKey(window_, key) == GLFW_PRESS; };
  CameraControls& c = in.camera;
  c.forward = held(GLFW_KEY_W);
  c.back = held(GLFW_KEY_S);
  c.left = held(GLFW_KEY_A);
  c.right = held(GLFW_KEY_D);
  c.down = held(GLFW_KEY_Q);
  c.up = held(GLFW_KEY_E);
  c.fast = held(GLFW_KEY_LEFT_SHIFT) || held(GLFW_KEY_RIGHT_SHIFT);
  c.wheel = uiWantsMouse ? 0.0f : wheel;

  WindowActions& a = in.actions;
  a.resetCamera = pressedOnce(GLFW_KEY_R, keys);
  a.togglePause = pressedOnce(GLFW_KEY_SPACE, keys);
  a.toggleUi = pressedOnce(GLFW_KEY_F1, keys);
  a.screenshot = pressedOnce(GLFW_KEY_F12, keys);
  a.recordPath = pressedOnce(GLFW_KEY_F9, keys);
  a.quit = pressedOnce(GLFW_KEY_ESCAPE, keys);

  double x = 0, y = 0;
  glfwGetCursorPos(window_, &x, &y);
  bool button = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS ||
                glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
  if (!button)
    dragging_ = false;
  else if (!dragging_ && !uiWantsMouse)
    dragging_ = true;  // a drag starting on the image
  else if (dragging_)
    c.lookPixels = {float(x - lastX_), float(y - lastY_)};
  lastX_ = x;
  lastY_ = y;
  return in;
}

}  // namespace qlight::game
