// Scripted steps for the demo window (`--script FRAME:ACTION`, for tests and timing runs):
// at a frame, what a user would do: resize the window, switch vsync, press "load settings"
// or "save settings", switch the cache points overlay, the denoiser or the panel; and capture the
// window (the image with the panel) as PNG.
#pragma once
#include <cstdint>
#include <string>

namespace qlight::game {

struct ScriptStep {
  enum class Action { Resize, Vsync, Load, Save, Points, Denoise, Panel, Capture };
  uint32_t frame = 0;
  Action action = Action::Resize;
  uint32_t width = 0, height = 0;  // Resize
  bool on = false;                 // Vsync, Points, Denoise, Panel
  std::string path;                // Load, Save, Capture
};

// Parses "FRAME:resize=WxH", "FRAME:vsync=on|off", "FRAME:load=FILE", "FRAME:save=FILE",
// "FRAME:points=on|off", "FRAME:denoise=on|off", "FRAME:panel=on|off" (F1) or
// "FRAME:capture=FILE".
// Throws std::invalid_argument, one line naming the step.
ScriptStep parseScriptStep(const std::string& text);

}  // namespace qlight::game
