#include "game/window_app.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "engine/gpu/pass_recorder.h"
#include "engine/scene/gltf_loader.h"
#include "engine/ui/swapchain_blit.h"
#include "game/context_setup.h"
#include "game/ui_guiding_panel.h"
#include "game/ui_panel.h"
#include "game/window_screenshot.h"
#include "shaders/shared/tonemap.h"

namespace qlight::game {
namespace {

// The first frame's render size: the requested window times the scale.
render::RenderSettings initialSettings(const DemoArgs& args) {
  render::RenderSettings s = args.settings;
  float scale = std::clamp(args.renderScale, 0.1f, 1.0f);
  s.width = std::max(1u, uint32_t(std::lround(args.windowWidth * scale)));
  s.height = std::max(1u, uint32_t(std::lround(args.windowHeight * scale)));
  return s;
}

// Settings whose change alters what the tracer computes (not just the display).
bool tracingDiffers(const render::RenderSettings& a, const render::RenderSettings& b) {
  return a.width != b.width || a.height != b.height || a.maxDepth != b.maxDepth ||
         a.seed != b.seed || a.estimator != b.estimator || a.russianRoulette != b.russianRoulette;
}

}  // namespace

WindowApp::WindowApp(const DemoArgs& args, const CommonOptions& common)
    : args_(args),
      asset_(scene::loadGltf(args.scene)),
      window_(args.windowWidth, args.windowHeight,
              "qlight: " + std::filesystem::path(args.scene).filename().string()),
      ctx_(createContext(common, true, ui::GlfwWindow::requiredInstanceExtensions(),
                         [this](VkInstance instance) { return window_.createSurface(instance); })),
      presenter_(*ctx_, window_),
      imgui_(*ctx_, window_, presenter_),
      world_(asset_, float(args.windowWidth) / float(std::max(args.windowHeight, 1u))),
      gpuScene_(*ctx_, asset_),
      wanted_(initialSettings(args)),
      renderScale_(std::clamp(args.renderScale, 0.1f, 1.0f)),
      tracer_(*ctx_, wanted_),
      display_(*ctx_),
      guidingWanted_(args.guiding),
      timer_(*ctx_),
      input_(window_.handle()) {
  clock_.duration = asset_.animationDuration();
  updateScenePose();
  resetCamera();
  guiding_ = std::make_unique<guiding::QGuiding>(*ctx_, guidingWanted_);
  guiding_->generatePoints(world_.registry(), gpuScene_);
}

// New guiding settings apply at once: strata changes reset the tables, the
// rest takes effect in the next frame. Guiding never biases the image, so
// accumulation goes on.
void WindowApp::applyGuiding(bool regenerate) {
  guiding_->setSettings(guidingWanted_);
  if (regenerate || guiding_->needsPoints()) guiding_->generatePoints(world_.registry(), gpuScene_);
}

WindowApp::~WindowApp() { vkDeviceWaitIdle(ctx_->device()); }

float WindowApp::renderAspect() const {
  return float(tracer_.settings().width) / float(tracer_.settings().height);
}

void WindowApp::updateScenePose() {
  world_.advance(clock_.time);  // animation -> transforms -> extract, by the scheduler
  gpuScene_.update(world_.draw());
}

void WindowApp::resetCamera() {
  render::CameraView start = world_.camera();
  // Half the scene's radius per second crosses a room in a few seconds.
  camera_.reset(start, 0.5f * std::max(asset_.bounds.radius(), 1e-3f));
}

void WindowApp::collectPreviousFrame(double seconds) {
  FrameSample sample;
  sample.seconds = seconds;
  sample.counters = tracer_.collectCounters();
  sample.gpuMs = timer_.collect(*ctx_);
  stats_.add(sample);
  guiding_->afterFrame(world_.registry());  // new points where camera paths found none
}

void WindowApp::handleActions(const WindowActions& a) {
  if (a.quit) window_.requestClose();
  if (a.toggleUi) uiVisible_ = !uiVisible_;
  if (a.togglePause) clock_.playing = !clock_.playing;
  if (a.resetCamera) resetCamera();
  if (a.screenshot) screenshotPending_ = true;
}

void WindowApp::applySettings(VkExtent2D extent) {
  wanted_.width = std::max(1u, uint32_t(std::lround(extent.width * renderScale_)));
  wanted_.height = std::max(1u, uint32_t(std::lround(extent.height * renderScale_)));
  if (tracingDiffers(wanted_, tracer_.settings())) {
    tracer_.setSettings(wanted_);  // restarts accumulation (reallocates on a new size)
  } else if (wanted_.samplesPerFrame != tracer_.settings().samplesPerFrame) {
    tracer_.setSamplesPerFrame(wanted_.samplesPerFrame);  // the image stays valid
  }
}

void WindowApp::recordFrame(const ui::PresentTarget& target) {
  VkCommandBuffer cmd = target.cmd;
  timer_.reset(cmd);
  gpu::PassRecorder recorder(*ctx_, cmd, &timer_);
  tracer_.recordFrame(recorder, gpuScene_, camera_.view(), guiding_->binder());
  guiding_->recordLearning(recorder);
  ui::DisplaySettings display;
  display.exposure = wanted_.exposure;
  display.tonemap =
      wanted_.tonemap == render::Tonemap::Aces ? shared::kTonemapAces : shared::kTonemapClamp;
  display.encodeSrgb = !presenter_.swapchain().encodesSrgb();
  display_.record(recorder, tracer_.accumulation(), display);
  recorder.finish();

  timer_.begin(cmd, "present.blit");
  ui::recordBlitToSwapchain(cmd, display_.output(), target.image, target.extent, VK_FILTER_LINEAR);
  timer_.end(cmd);
  timer_.begin(cmd, "imgui");
  imgui_.render(target, presenter_.overlayRenderPass());
  timer_.end(cmd);
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

    imgui_.newFrame();
    FrameInput input =
        input_.read(imgui_.wantsMouse(), imgui_.wantsKeyboard(), ImGui::GetIO().MouseWheel);
    handleActions(input.actions);
    camera_.update(input.camera, step);
    bool posed = clock_.advance(step);
    if (uiVisible_) {
      StatsView view{&stats_,
                     tracer_.accumulatedSamples(),
                     tracer_.settings().width,
                     tracer_.settings().height,
                     ctx_->deviceName(),
                     ctx_->deviceName().find("llvmpipe") == std::string::npos};
      PanelChanges changes = drawQlightPanel(view, wanted_, renderScale_, clock_, camera_, [&] {
        GuidingPanelResult g = drawGuidingSection(guidingWanted_, guiding_->stats());
        if (g.changed || g.regenerate) applyGuiding(g.regenerate);
      });
      posed |= changes.scenePose;
      if (changes.resetCamera) resetCamera();
    }
    applySettings(target->extent);
    if (posed) {
      updateScenePose();
      // Moving lights and objects invalidate the image: restart, or fade the history.
      if (wanted_.temporalBlend > 0.0f) tracer_.fadeAccumulation(wanted_.temporalBlend);
      else tracer_.resetAccumulation();
    }
    recordFrame(*target);
    presenter_.endFrame(*target);
    frameInFlight_ = true;
    ++frames;

    if (screenshotPending_) {
      writeScreenshot(tracer_, nextScreenshotPath(args_.outDir), wanted_.exposure, wanted_.tonemap);
      screenshotPending_ = false;
    }
    if (args_.exitAfterFrames && frames >= args_.exitAfterFrames) break;
  }
  vkDeviceWaitIdle(ctx_->device());
  double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  std::printf("qlight demo: %u frames in a %ux%u window (render %ux%u) in %.2f s, %.1f ms/frame\n",
              frames, presenter_.swapchain().extent().width, presenter_.swapchain().extent().height,
              tracer_.settings().width, tracer_.settings().height, seconds,
              1e3 * seconds / std::max(frames, 1u));
  if (!args_.screenshotAtExit.empty())
    writeScreenshot(tracer_, args_.screenshotAtExit, wanted_.exposure, wanted_.tonemap);
  return finishContext(*ctx_);
}

}  // namespace qlight::game
