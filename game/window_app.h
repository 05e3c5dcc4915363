// The interactive demo: a window presenting the path tracer's accumulating
// image, a free camera, the animated scene and the ImGui panel. One frame in
// flight: the path tracer's per-frame buffers are single-buffered.
#pragma once
#include <chrono>
#include <memory>

#include "engine/gpu/context.h"
#include "engine/scene/scene_asset.h"
#include "engine/session/renderer.h"
#include "engine/ui/display_filter.h"
#include "engine/ui/display_pass.h"
#include "engine/ui/glfw_window.h"
#include "engine/ui/imgui_layer.h"
#include "engine/ui/presenter.h"
#include "engine/ui/window_capture.h"
#include "game/demo_window.h"
#include "game/dynamic_resolution.h"
#include "game/settings.h"
#include "game/ui_guide_views.h"
#include "game/ui_window_panel.h"
#include "game/window_camera.h"
#include "game/window_camera_path.h"
#include "game/window_input.h"
#include "game/window_scene.h"
#include "game/window_stats.h"

namespace qlight::game {

class WindowApp {
 public:
  WindowApp(const DemoArgs& args, const CommonOptions& common);
  WindowApp(const WindowApp&) = delete;
  WindowApp& operator=(const WindowApp&) = delete;
  ~WindowApp();

  // The frame loop; returns the exit code (validation messages make it non-zero).
  int run();

 private:
  using Clock = std::chrono::steady_clock;
  void collectPreviousFrame(double seconds);
  void handleActions(const WindowActions& actions);
  // The tracer follows the edited settings and the window size (restarting
  // accumulation when what it computes changes).
  void applySettings(VkExtent2D windowExtent, float scale);
  // The camera after this frame's input (or the scripted move, or the path playing); true
  // when it moved.
  bool moveCamera(FrameInput input, uint32_t frame, float step);
  void recordFrame(const ui::PresentTarget& target);
  void resetCamera();
  void registerDisplay();  // the present phase's tonemap pass

  // The settings file (window_app_settings.cpp): what the panel shows, as a file would
  // hold it; taking a loaded one; the panel's buttons; the scripted steps of this frame.
  Settings currentSettings() const;
  void useSettings(const Settings& s);
  void saveSettings(const std::string& path);
  void loadSettings(const std::string& path);
  void report(const std::string& message, bool problem);  // in the panel and on stderr
  void drawWindowPanel();
  void runScript(uint32_t frame);

  DemoArgs args_;
  scene::SceneAsset asset_;
  ui::GlfwWindow window_;
  std::unique_ptr<gpu::Context> ctx_;
  ui::Presenter presenter_;
  ui::ImGuiLayer imgui_;
  render::RenderSettings wanted_;  // what the panel edits; the tracer follows
  float renderScale_;              // the user's: the size a still camera accumulates at
  DynamicResolution dynamic_;      // the size while the camera moves
  float lowestScale_;              // the smallest the dynamic resolution went, for the exit line
  static constexpr uint32_t kStartupFrames = 2;  // left out of the moving figure
  double movingSeconds_ = 0;  // frame time spent while the camera moved, and the frames
  uint32_t movingFrames_ = 0;
  session::Renderer renderer_;  // the frame: scene entities, cache points, tracer, guide
  ui::DisplayPass display_;
  ui::DisplayFilter filter_;  // temporal reuse and the denoiser, display only
  ui::DisplayFilterSettings filterSettings_;
  ui::WindowCapture capture_;  // --script FRAME:capture=FILE: the window with its panel
  std::string capturePath_;    // set for the frame being recorded
  guiding::GuidingSettings guidingWanted_;
  GuideViews guideViews_;  // cache points over the image, Q under the cursor
  InputReader input_;
  FreeCamera camera_;
  WindowCameraPath paths_;   // F9 recording, --camera-path playback
  render::CameraView view_;  // what this frame renders: the free camera's or the path's
  SceneClock clock_;
  FrameStats stats_;
  WindowPanel windowPanel_;
  bool uiVisible_ = true;
  bool frameInFlight_ = false;
  bool screenshotPending_ = false;
};

}  // namespace qlight::game
