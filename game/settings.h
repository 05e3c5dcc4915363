// Every setting a user can set, together: what a settings file saves and replays.
#pragma once
#include <glm/glm.hpp>
#include <optional>
#include <string>

#include "engine/guiding/guiding_settings.h"
#include "engine/render/render_settings.h"

namespace qlight::game {

// The demo window's own settings (the render size follows the window there).
struct WindowSettings {
  float renderScale = 0.5f;      // render size as a share of the window's (a still camera's)
  float targetFrameMs = 100.0f;  // dynamic resolution while the camera moves (0: off)
  bool vsync = false;            // FIFO presentation; off: every frame the tracer makes
};

// The light from infinitely far away (game/environment_choice.h): a map or a uniform sky, or
// neither (then a scene without any light gets the fallback sky). Read when the scene loads.
struct EnvironmentSettings {
  std::string file;              // --env: equirectangular .hdr or .exr ("": none)
  std::optional<glm::vec3> sky;  // --sky R,G,B: uniform radiance (a map wins over it)
  float strength = 1.0f;         // --env-strength: multiplies the map or the sky
  float rotationDegrees = 0.0f;  // --env-rotation: about +Y, right-handed

  bool chosen() const { return !file.empty() || sky.has_value(); }
};

struct Settings {
  render::RenderSettings render;
  guiding::GuidingSettings guiding;
  WindowSettings window;
  EnvironmentSettings environment;
};

}  // namespace qlight::game
