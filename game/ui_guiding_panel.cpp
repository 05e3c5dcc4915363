#include "game/ui_guiding_panel.h"

#include <imgui.h>

#include <algorithm>

#include "shaders/shared/strata.h"

namespace qlight::game {

GuidingPanelResult drawGuidingSection(guiding::GuidingSettings& s,
                                      const guiding::GuidingStats& st) {
  GuidingPanelResult r;
  guiding::GuidingSettings before = s;
  ImGui::Checkbox("guided sampling", &s.enabled);
  ImGui::SameLine();
  ImGui::Checkbox("learn", &s.learn);
  ImGui::SameLine();
  bool returns = s.target == guiding::LearningTarget::Returns;
  ImGui::Checkbox("from returns", &returns);  // else D&K's one-step TD target
  s.target = returns ? guiding::LearningTarget::Returns : guiding::LearningTarget::TdStep;
  int rows = int(s.rows), cols = int(s.cols);
  ImGui::SliderInt("strata rows", &rows, 1, 32);
  ImGui::SliderInt("strata cols", &cols, 1, 32);
  s.rows = uint32_t(rows);
  s.cols = uint32_t(std::min(cols, int(shared::kMaxStrata) / rows));  // R x C <= kMaxStrata
  ImGui::SliderFloat("alpha min", &s.alphaMin, 1e-5f, 0.5f, "%.5f", ImGuiSliderFlags_Logarithmic);
  ImGui::SliderFloat("alpha max", &s.alphaMax, 1e-4f, 1.0f, "%.4f", ImGuiSliderFlags_Logarithmic);
  s.alphaMax = std::max(s.alphaMax, s.alphaMin);
  ImGui::SliderFloat("guided share", &s.selectProbability, 0.0f, 0.95f, "%.2f");
  ImGui::Checkbox("learned light selection", &s.lightLearning);
  ImGui::SliderFloat("light mix", &s.lightMix, 0.0f, 0.95f, "%.2f");
  r.changed = s.enabled != before.enabled || s.learn != before.learn || s.target != before.target ||
              s.rows != before.rows || s.cols != before.cols || s.alphaMin != before.alphaMin ||
              s.alphaMax != before.alphaMax || s.selectProbability != before.selectProbability ||
              s.lightLearning != before.lightLearning || s.lightMix != before.lightMix;
  r.regenerate = ImGui::Button("regenerate points");
  ImGui::Text("%u cache points (%u from camera paths)", st.points, st.spawnedPoints);
  ImGui::Text("%u strata, %u lights learned", st.strata, st.lightsLearned);
  ImGui::TextDisabled("rejection %.3f..%.3f, search %.3f", st.rejectionMin, st.rejectionMax,
                      st.searchRadius);
  return r;
}

}  // namespace qlight::game
