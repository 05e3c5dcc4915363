// The interactive demo: a GLFW window, the path tracer's image presented each
// frame, fly controls, and the Dear ImGui panel.
#pragma once
#include <string>

#include "engine/render/render_settings.h"
#include "game/cli_options.h"

namespace qlight::game {

struct DemoArgs {
  std::string scene = "animated_light.gltf";
  uint32_t frames = 60;
  float fps = 24.0f;
  float moveSeconds = 1.5f;
  uint32_t saveEvery = 20;
  std::string outDir = "out/demo";
  bool headless = false;
  render::RenderSettings settings;
};

// Runs until the window closes; returns the exit code. glfwInit() has succeeded.
int runWindowed(const DemoArgs& args, const CommonOptions& common);

}  // namespace qlight::game
