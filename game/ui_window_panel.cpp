#include "game/ui_window_panel.h"

#include <imgui.h>

#include <algorithm>

namespace qlight::game {

WindowPanel::WindowPanel(const std::string& settingsPath) {
  const std::string& initial = settingsPath.empty() ? std::string(kDefaultPath) : settingsPath;
  std::copy_n(initial.begin(), std::min(initial.size(), path.size() - 1), path.begin());
}

WindowPanelActions drawWindowSection(WindowPanel& panel, bool& vsync) {
  WindowPanelActions a;
  a.vsyncChanged = ImGui::Checkbox("vsync", &vsync);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("wait for vertical blank (FIFO); off shows every frame the tracer makes");
  ImGui::InputText("settings file", panel.path.data(), panel.path.size());
  a.save = ImGui::Button("save settings");
  ImGui::SameLine();
  a.load = ImGui::Button("load settings");
  if (!panel.message.empty()) {
    const ImVec4 colour =
        panel.messageIsProblem ? ImVec4(1.0f, 0.75f, 0.3f, 1.0f) : ImVec4(0.6f, 0.9f, 0.6f, 1.0f);
    ImGui::PushStyleColor(ImGuiCol_Text, colour);
    ImGui::TextWrapped("%s", panel.message.c_str());
    ImGui::PopStyleColor();
  }
  return a;
}

}  // namespace qlight::game
