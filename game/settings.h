// Every setting a user can set, together: what a settings file saves and replays.
#pragma once
#include "engine/guiding/guiding_settings.h"
#include "engine/render/render_settings.h"

namespace qlight::game {

// The demo window's own settings (the render size follows the window there).
struct WindowSettings {
  float renderScale = 0.5f;      // render size as a share of the window's (a still camera's)
  float targetFrameMs = 100.0f;  // dynamic resolution while the camera moves (0: off)
  bool vsync = false;            // FIFO presentation; off: every frame the tracer makes
};

struct Settings {
  render::RenderSettings render;
  guiding::GuidingSettings guiding;
  WindowSettings window;
};

}  // namespace qlight::game
