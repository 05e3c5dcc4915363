// Scripted steps for the demo window (`--script FRAME:ACTION`, for tests and timing runs):
// at a frame, what a user would do: resize the window, switch vsync, press "load settings"
// or "save settings".
#pragma once
#include <cstdint>
#include <string>

namespace qlight::game {

struct ScriptStep {
  enum class Action { Resize, Vsync, Load, Save };
  uint32_t frame = 0;
  Action action = Action::Resize;
  uint32_t width = 0, height = 0;  // Resize
  bool on = false;                 // Vsync
  std::string path;                // Load, Save
};

// Parses "FRAME:resize=WxH", "FRAME:vsync=on|off", "FRAME:load=FILE" or "FRAME:save=FILE".
// Throws std::invalid_argument, one line naming the step.
ScriptStep parseScriptStep(const std::string& text);

}  // namespace qlight::game
