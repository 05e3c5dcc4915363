// WindowApp and the settings file: the panel's "save settings" and "load settings", the
// vsync switch, and the scripted steps that press them (--script).
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>

#include "game/settings_file.h"
#include "game/window_app.h"

namespace qlight::game {

Settings WindowApp::currentSettings() const {
  // The environment is the one the window started with (it loads with the scene).
  Settings s{wanted_, guidingWanted_, {}, args_.environment};
  s.window.renderScale = renderScale_;
  s.window.targetFrameMs = dynamic_.enabled ? dynamic_.targetMs : 0.0f;
  s.window.vsync = presenter_.vsync();
  // The size a still camera accumulates at (not one lowered while moving), so that
  // `qlight render --settings` replays the window's image.
  const VkExtent2D extent = presenter_.swapchain().extent();
  s.render.width = std::max(1u, uint32_t(std::lround(extent.width * renderScale_)));
  s.render.height = std::max(1u, uint32_t(std::lround(extent.height * renderScale_)));
  return s;
}

void WindowApp::useSettings(const Settings& s) {
  guiding::GuidingSettings guiding = s.guiding;
  guiding.seed = s.render.seed;   // as on the command line
  renderer_.setGuiding(guiding);  // first: what may throw (a table the device cannot hold)
  guidingWanted_ = guiding;
  // The window's size and the render scale set the render size (applySettings).
  const uint32_t width = wanted_.width, height = wanted_.height;
  wanted_ = s.render;
  wanted_.width = width, wanted_.height = height;
  renderScale_ = std::clamp(s.window.renderScale, 0.1f, 1.0f);
  dynamic_.enabled = s.window.targetFrameMs > 0.0f;
  if (dynamic_.enabled) dynamic_.targetMs = s.window.targetFrameMs;
  presenter_.setVsync(s.window.vsync);
}

void WindowApp::report(const std::string& message, bool problem) {
  windowPanel_.message = message;
  windowPanel_.messageIsProblem = problem;
  std::fprintf(stderr, "qlight demo: %s\n", message.c_str());
}

void WindowApp::saveSettings(const std::string& path) {
  try {
    saveSettingsFile(path, currentSettings());
    report("saved settings to " + path, false);
  } catch (const std::exception& e) {
    report(e.what(), true);
  }
}

void WindowApp::loadSettings(const std::string& path) {
  try {
    Settings s = currentSettings();
    const std::vector<std::string> warnings = loadSettingsFile(path, s);
    useSettings(s);
    std::string message = "loaded settings from " + path;
    for (const std::string& w : warnings) message += "\nwarning: " + w;
    report(message, !warnings.empty());
  } catch (const std::exception& e) {  // the window goes on with what it had
    report(e.what(), true);
  }
}

void WindowApp::drawWindowPanel() {
  bool vsync = presenter_.vsync();
  const WindowPanelActions a = drawWindowSection(windowPanel_, vsync);
  if (a.vsyncChanged) presenter_.setVsync(vsync);  // the swapchain is rebuilt next frame
  if (a.save) saveSettings(windowPanel_.path.data());
  if (a.load) loadSettings(windowPanel_.path.data());
}

void WindowApp::runScript(uint32_t frame) {
  for (const ScriptStep& step : args_.script) {
    if (step.frame != frame) continue;
    switch (step.action) {
      case ScriptStep::Action::Resize:  // as a user dragging the border: events follow
        glfwSetWindowSize(window_.handle(), int(step.width), int(step.height));
        break;
      case ScriptStep::Action::Vsync:
        presenter_.setVsync(step.on);
        break;
      case ScriptStep::Action::Load:
        loadSettings(step.path);
        break;
      case ScriptStep::Action::Save:
        saveSettings(step.path);
        break;
      case ScriptStep::Action::Points:
        guideViews_.settings.pointsOverlay = step.on;
        break;
      case ScriptStep::Action::Denoise:
        filterSettings_.denoise = step.on;
        break;
      case ScriptStep::Action::Panel:
        uiVisible_ = step.on;
        break;
      case ScriptStep::Action::Capture:
        capturePath_ = step.path;  // after this frame's panel is drawn
        break;
    }
  }
}

}  // namespace qlight::game
