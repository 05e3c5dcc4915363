#include "game/demo_window.h"

#include <GLFW/glfw3.h>

#include <cstdio>
#include <exception>

#include "game/window_app.h"

namespace qlight::game {

int runWindowed(const DemoArgs& args, const CommonOptions& common) {
  int code = 1;
  try {
    WindowApp app(args, common);
    code = app.run();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "qlight demo: window mode failed: %s\n", e.what());
    code = 1;
  }
  glfwTerminate();
  return code;
}

}  // namespace qlight::game
