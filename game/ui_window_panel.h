// The "Window" section of the demo panel: vsync, and saving or loading the settings file
// (game/settings_file.h) at a path typed in the panel. Plain state in, what was pressed
// out; the window does the work and reports back through `message`.
#pragma once
#include <array>
#include <string>

namespace qlight::game {

struct WindowPanel {
  static constexpr const char* kDefaultPath = "qlight_settings.json";  // working directory
  explicit WindowPanel(const std::string& settingsPath);
  std::array<char, 1024> path{};  // the text field
  std::string message;            // the last save or load: done, or its warnings or error
  bool messageIsProblem = false;  // shown in the warning colour
};

struct WindowPanelActions {
  bool vsyncChanged = false;
  bool save = false;
  bool load = false;
};

WindowPanelActions drawWindowSection(WindowPanel& panel, bool& vsync);

}  // namespace qlight::game
