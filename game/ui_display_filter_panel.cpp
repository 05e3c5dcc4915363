#include "game/ui_display_filter_panel.h"

#include <imgui.h>

namespace qlight::game {

void drawDisplayFilterSection(ui::DisplayFilterSettings& s) {
  constexpr ImGuiSliderFlags kClamp = ImGuiSliderFlags_AlwaysClamp;
  ImGui::Checkbox("reuse history when moving", &s.reuseHistory);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("reproject the last frame where the same surface is still in view");
  if (s.reuseHistory)
    ImGui::SliderFloat("history frames", &s.historyFrames, 1.0f, 64.0f, "%.0f", kClamp);
  ImGui::Checkbox("denoise", &s.denoise);
  if (s.denoise) {
    ImGui::SliderFloat("strength", &s.strength, 0.1f, 8.0f, "%.2f",
                       ImGuiSliderFlags_Logarithmic | kClamp);
    ImGui::SliderInt("iterations", &s.iterations, 1, 6, "%d", kClamp);
  }
  ImGui::TextDisabled("display only: screenshots and outputs stay unfiltered");
}

}  // namespace qlight::game
