// The interactive demo: a GLFW window, the path tracer's image presented each
// frame, fly controls, and the Dear ImGui panel.
#pragma once
#include <string>
#include <vector>

#include "engine/render/render_settings.h"
#include "game/camera_path.h"
#include "game/common_options.h"
#include "game/settings.h"
#include "game/window_script.h"

namespace qlight::game {

constexpr uint32_t kMaxDemoFrames = 100000;  // headless frames in one run

struct DemoArgs {
  std::string scene = "door_ajar_moving_light.gltf";
  uint32_t frames = 60;
  float fps = 24.0f;
  float moveSeconds = 1.5f;
  uint32_t saveEvery = 20;
  std::string outDir = "out/demo";
  bool headless = false;
  std::string camera = "sway";  // headless: the sway around the scene's camera, or "gltf": its own
  std::string cameraPathFile;   // --camera-path: played instead (window: then the free camera)
  CameraPath cameraPath;        // loaded from cameraPathFile before the device starts
  std::string recordPath;       // window: F9 records here ("": outDir/camera_path.json)
  render::RenderSettings settings;
  guiding::GuidingSettings guiding;  // Q-learned guiding (on by default)
  GuidingCli guidingCli;
  EnvironmentSettings environment;  // --env, --sky: read when the scene loads
  std::string skyText;              // --sky's text
  // Window mode: the render is the window's size times window.renderScale (a smaller
  // render keeps a software rasterizer interactive); settings.width/height are unused.
  uint32_t windowWidth = 960;
  uint32_t windowHeight = 540;
  WindowSettings window;            // render scale, dynamic resolution, vsync
  std::string settingsFile;         // --settings: also where the panel saves and loads
  uint32_t scriptedMoveFrames = 0;  // fly forward for the first N frames (tests, timing)
  std::vector<ScriptStep> script;   // --script: resize, vsync, load, save at given frames
  uint32_t exitAfterFrames = 0;     // 0: run until the window closes
  std::string screenshotAtExit;     // PNG of the render written when the window closes
  bool showCachePoints = false;     // the cache points overlay from the start
  bool reuseHistory = true;         // display: reproject the last frame while moving
  bool denoise = true;              // display: the a-trous denoiser
  std::vector<float> inspectAt;     // window pixel whose Q is shown instead of the cursor's
};

// Runs until the window closes; returns the exit code (non-zero after printing
// one error line when the window, surface or swapchain fails). glfwInit() has succeeded.
int runWindowed(const DemoArgs& args, const CommonOptions& common);

}  // namespace qlight::game
