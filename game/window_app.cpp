#include "game/window_app.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "engine/gltf/gltf_loader.h"
#include "engine/gpu/pass_recorder.h"
#include "engine/ui/swapchain_blit.h"
#include "game/context_setup.h"
#include "game/environment_choice.h"
#include "game/ui_display_filter_panel.h"
#include "game/ui_guiding_panel.h"
#include "game/ui_panel.h"
#include "game/window_screenshot.h"
#include "shaders/shared/tonemap.h"

namespace qlight::game {
namespace {

// The first frame's render size: the requested window times the scale.
render::RenderSettings initialSettings(const DemoArgs& args) {
  render::RenderSettings s = args.settings;
  float scale = std::clamp(args.window.renderScale, 0.1f, 1.0f);
  s.width = std::max(1u, uint32_t(std::lround(args.windowWidth * scale)));
  s.height = std::max(1u, uint32_t(std::lround(args.windowHeight * scale)));
  return s;
}

const char* presentModeName(VkPresentModeKHR mode) {
  switch (mode) {
    case VK_PRESENT_MODE_FIFO_KHR:
      return "FIFO";
    case VK_PRESENT_MODE_MAILBOX_KHR:
      return "MAILBOX";
    case VK_PRESENT_MODE_IMMEDIATE_KHR:
      return "IMMEDIATE";
    default:
      return "other";
  }
}

// Settings whose change alters what the tracer computes (not just the display).
bool tracingDiffers(const render::RenderSettings& a, const render::RenderSettings& b) {
  return a.width != b.width || a.height != b.height || a.maxDepth != b.maxDepth ||
         a.seed != b.seed || a.estimator != b.estimator || a.russianRoulette != b.russianRoulette;
}

scene::SceneAsset loadSceneWithEnvironment(const std::string& file,
                                           const EnvironmentSettings& env) {
  scene::SceneAsset asset = gltf::loadGltf(file);
  attachEnvironment(asset, env);
  return asset;
}

}  // namespace

WindowApp::WindowApp(const DemoArgs& args, const CommonOptions& common)
    : args_(args),
      asset_(loadSceneWithEnvironment(args.scene, args.environment)),
      window_(args.windowWidth, args.windowHeight,
              "qlight: " + std::filesystem::path(args.scene).filename().string()),
      ctx_(createContext(common, true, ui::GlfwWindow::requiredInstanceExtensions(),
                         [this](VkInstance instance) { return window_.createSurface(instance); })),
      presenter_(*ctx_, window_, args.window.vsync),
      imgui_(*ctx_, window_, presenter_),
      wanted_(initialSettings(args)),
      renderScale_(std::clamp(args.window.renderScale, 0.1f, 1.0f)),
      lowestScale_(renderScale_),
      renderer_(*ctx_, asset_, wanted_, args.guiding,
                float(args.windowWidth) / float(std::max(args.windowHeight, 1u))),
      display_(*ctx_),
      filter_(*ctx_),
      capture_(*ctx_),
      guidingWanted_(args.guiding),
      input_(window_.handle()),
      paths_(args, renderer_.world().camera().yfov),
      windowPanel_(args.settingsFile) {
  clock_.duration = asset_.animationDuration();
  dynamic_.enabled = args.window.targetFrameMs > 0.0f;
  if (dynamic_.enabled) dynamic_.targetMs = args.window.targetFrameMs;
  dynamic_.scale = renderScale_;
  filterSettings_.reuseHistory = args.reuseHistory;
  filterSettings_.denoise = args.denoise;
  guideViews_.settings.pointsOverlay = args.showCachePoints;
  resetCamera();
  registerDisplay();
}

WindowApp::~WindowApp() { vkDeviceWaitIdle(ctx_->device()); }

void WindowApp::registerDisplay() {
  renderer_.scheduler()
      .add("display")
      .phase(ecs::Phase::Present)
      .reads<render::PathTracer, session::FrameRecording, session::FrameView>()
      .writes<ui::DisplayPass>()
      .run([this](ecs::Registry& r) {
        gpu::PassRecorder& recorder = *r.resource<session::FrameRecording>().recorder;
        const render::PathTracer& tracer = renderer_.tracer();
        const gpu::Image* shown = &tracer.accumulation();
        if (filterSettings_.active()) {
          filterSettings_.maxLuminance = 4.0f / std::max(wanted_.exposure, 1e-6f);
          filter_.record(recorder, renderer_.scene(), tracer.accumulation(),
                         tracer.keptOfPrevious(), r.resource<session::FrameView>().camera,
                         filterSettings_);
          shown = &filter_.output();
        }
        ui::DisplaySettings display;
        display.exposure = wanted_.exposure;
        display.tonemap =
            wanted_.tonemap == image::Tonemap::Aces ? shared::kTonemapAces : shared::kTonemapClamp;
        display.encodeSrgb = !presenter_.swapchain().encodesSrgb();
        display_.record(recorder, *shown, display);
      });
}

void WindowApp::resetCamera() {
  render::CameraView start = renderer_.world().camera();
  // Half the scene's radius per second crosses a room in a few seconds.
  camera_.reset(start, 0.5f * std::max(asset_.bounds.radius(), 1e-3f));
  view_ = camera_.view();
}

void WindowApp::collectPreviousFrame(double seconds) {
  session::FrameResult frame = renderer_.collect();  // and new points where paths found none
  FrameSample sample;
  sample.seconds = seconds;
  sample.counters = frame.counters;
  sample.gpuMs = std::move(frame.gpuMs);
  stats_.add(sample);
}

void WindowApp::handleActions(const WindowActions& a) {
  if (a.quit) window_.requestClose();
  if (a.toggleUi) uiVisible_ = !uiVisible_;
  if (a.togglePause) clock_.playing = !clock_.playing;
  if (a.resetCamera) resetCamera();
  if (a.screenshot) screenshotPending_ = true;
  if (a.recordPath) paths_.toggleRecording();
}

bool WindowApp::moveCamera(FrameInput input, uint32_t frame, float step) {
  const render::CameraView before = view_;
  if (std::optional<render::CameraView> played = paths_.play(step)) {
    view_ = *played;
    camera_.reset(view_, camera_.speed);  // where the free camera starts when the path ends
  } else {
    if (frame < args_.scriptedMoveFrames) {
      // Forward and back in turns of kScriptedLeg frames, turning as it goes: the camera
      // keeps moving for the measurement but stays in the room it started in.
      constexpr uint32_t kScriptedLeg = 8;
      const bool outward = (frame / kScriptedLeg) % 2 == 0;
      input.camera.forward = outward;
      input.camera.back = !outward;
      input.camera.lookPixels.x += outward ? 12.0f : -12.0f;
    }
    camera_.update(input.camera, step);
    view_ = camera_.view();
  }
  paths_.record(view_, step);
  return view_ != before;
}

void WindowApp::applySettings(VkExtent2D extent, float scale) {
  render::PathTracer& tracer = renderer_.tracer();
  wanted_.width = std::max(1u, uint32_t(std::lround(extent.width * scale)));
  wanted_.height = std::max(1u, uint32_t(std::lround(extent.height * scale)));
  if (tracingDiffers(wanted_, tracer.settings())) {
    tracer.setSettings(wanted_);  // restarts accumulation (reallocates on a new size)
    return;
  }
  // These leave the accumulated image valid.
  if (wanted_.samplesPerFrame != tracer.settings().samplesPerFrame)
    tracer.setSamplesPerFrame(wanted_.samplesPerFrame);
  if (wanted_.temporalBlend != tracer.settings().temporalBlend)
    tracer.setTemporalBlend(wanted_.temporalBlend);
}

void WindowApp::recordFrame(const ui::PresentTarget& target) {
  VkCommandBuffer cmd = target.cmd;
  renderer_.record(cmd);  // trace, learn, present (the display pass)
  gpu::GpuTimer& timer = renderer_.timer();
  timer.begin(cmd, "present.blit");
  ui::recordBlitToSwapchain(cmd, display_.output(), target.image, target.extent, VK_FILTER_LINEAR);
  timer.end(cmd);
  timer.begin(cmd, "imgui");
  imgui_.render(target, presenter_.overlayRenderPass());
  timer.end(cmd);
  if (!capturePath_.empty() && presenter_.swapchain().copyable())
    capture_.record(cmd, target.image, target.extent, presenter_.swapchain().format());
}

int WindowApp::run() {
  uint32_t frames = 0;
  Clock::time_point start = Clock::now(), last = start;
  while (!window_.shouldClose()) {
    glfwPollEvents();
    std::optional<ui::PresentTarget> target = presenter_.beginFrame();
    Clock::time_point now = Clock::now();
    double dt = std::chrono::duration<double>(now - last).count();
    last = now;
    // beginFrame waited for the previous frame: its counters and timings are final.
    if (frameInFlight_) collectPreviousFrame(dt);
    frameInFlight_ = false;
    if (!target) {  // minimized: nothing to draw into
      glfwWaitEventsTimeout(0.1);
      continue;
    }
    float step = float(std::min(dt, 0.25));  // a stall must not fling the camera

    runScript(frames);
    imgui_.newFrame();
    FrameInput input =
        input_.read(imgui_.wantsMouse(), imgui_.wantsKeyboard(), ImGui::GetIO().MouseWheel);
    handleActions(input.actions);
    const bool moved = moveCamera(input, frames, step);
    // Frames 1 and 2 carry the start-up (lavapipe builds pipelines at their first dispatches):
    // the moving figure leaves them out, as a frame counter leaves out loading.
    if (moved && frames > kStartupFrames) movingSeconds_ += dt, ++movingFrames_;
    // The previous frame's time (one frame in flight) sets the size of this one.
    const float scale = dynamic_.update(renderScale_, 1e3 * dt, moved);
    lowestScale_ = std::min(lowestScale_, scale);
    clock_.advance(step);
    const render::PathTracer& tracer = renderer_.tracer();
    if (uiVisible_) {
      StatsView view{&stats_, tracer.accumulatedSamples(), tracer.settings().width,
                     tracer.settings().height, ctx_->deviceName()};
      auto windowUi = [&] { drawWindowPanel(); };
      view.cameraPath = paths_.status();
      PanelChanges changes =
          drawQlightPanel(view, wanted_, renderScale_, dynamic_, clock_, camera_, windowUi, [&] {
            guiding::GuidingStats learned =
                renderer_.guide() ? renderer_.guide()->stats() : guiding::GuidingStats{};
            GuidingPanelResult g = drawGuidingSection(guidingWanted_, learned);
            // Strata changes reset the tables, the rest applies from the next frame; guiding
            // never biases the image, so accumulation goes on.
            if (g.changed || g.regenerate) renderer_.setGuiding(guidingWanted_, g.regenerate);
            drawGuideViewControls(guideViews_.settings);
          });
      if (changes.resetCamera) resetCamera();
      if (ImGui::Begin("qlight")) {  // appends to the panel
        if (ImGui::CollapsingHeader("Display")) drawDisplayFilterSection(filterSettings_);
      }
      ImGui::End();
      const ImGuiIO& io = ImGui::GetIO();
      if (args_.inspectAt.size() == 2)  // scripted runs and screenshots
        guideViews_.draw(renderer_, view_, io.DisplaySize,
                         ImVec2(args_.inspectAt[0], args_.inspectAt[1]), true);
      else
        guideViews_.draw(renderer_, view_, io.DisplaySize, io.MousePos, !imgui_.wantsMouse());
    }
    applySettings(target->extent, dynamic_.scale);
    // Simulate, extract, upload: a moved light or object restarts or fades the image.
    renderer_.update(clock_.time, view_);
    recordFrame(*target);
    presenter_.endFrame(*target);
    frameInFlight_ = true;
    ++frames;
    if (!capturePath_.empty()) {  // scripted only: waiting for the frame costs nothing there
      vkDeviceWaitIdle(ctx_->device());
      if (capture_.write(capturePath_))
        std::printf("qlight demo: window captured to %s\n", capturePath_.c_str());
      else
        std::printf("qlight demo: window not captured: the surface's images cannot be copied\n");
      capturePath_.clear();
    }

    if (screenshotPending_) {
      writeScreenshot(renderer_.tracer(), nextScreenshotPath(args_.outDir), wanted_.exposure,
                      wanted_.tonemap);
      screenshotPending_ = false;
    }
    if (args_.exitAfterFrames && frames >= args_.exitAfterFrames) break;
  }
  vkDeviceWaitIdle(ctx_->device());
  paths_.finish();
  double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  std::printf("qlight demo: %u frames in a %ux%u window (render %ux%u) in %.2f s, %.1f ms/frame\n",
              frames, presenter_.swapchain().extent().width, presenter_.swapchain().extent().height,
              renderer_.tracer().settings().width, renderer_.tracer().settings().height, seconds,
              1e3 * seconds / std::max(frames, 1u));
  std::printf(
      "qlight demo: render scale %.2f, lowest %.2f while moving (target %.0f ms%s); "
      "%u frames moving at %.1f ms/frame (after frame %u)\n",
      dynamic_.scale, lowestScale_, dynamic_.targetMs,
      dynamic_.enabled ? "" : ", dynamic resolution off", movingFrames_,
      1e3 * movingSeconds_ / std::max(movingFrames_, 1u), kStartupFrames);
  std::printf("qlight demo: GPU ms per frame (last frames): %s\n", passTimesLine(stats_).c_str());
  if (const std::string views = guideViews_.summary(); !views.empty())
    std::printf("qlight demo: guide views: %s\n", views.c_str());
  std::printf("qlight demo: vsync %s (%s presentation), %u swapchains built\n",
              presenter_.vsync() ? "on" : "off",
              presentModeName(presenter_.swapchain().presentMode()), presenter_.recreations());
  if (!args_.screenshotAtExit.empty())
    writeScreenshot(renderer_.tracer(), args_.screenshotAtExit, wanted_.exposure, wanted_.tonemap);
  return finishContext(*ctx_);
}

}  // namespace qlight::game
