#include "game/ui_guiding_panel.h"

#include <imgui.h>

#include <algorithm>

#include "shaders/shared/strata.h"

namespace qlight::game {
namespace {
// Typed values (ctrl+click) stay in range too: an alpha-min of 0 must not reach the guide.
constexpr ImGuiSliderFlags kClamp = ImGuiSliderFlags_AlwaysClamp;
constexpr ImGuiSliderFlags kLogClamp = ImGuiSliderFlags_Logarithmic | kClamp;
}  // namespace

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
  ImGui::SliderInt("strata rows", &rows, 1, 32, "%d", kClamp);
  ImGui::SliderInt("strata cols", &cols, 1, 32, "%d", kClamp);
  s.rows = uint32_t(rows);
  s.cols = uint32_t(std::min(cols, int(shared::kMaxStrata) / rows));  // R x C <= kMaxStrata
  ImGui::SliderFloat("alpha min", &s.alphaMin, 1e-5f, 0.5f, "%.5f", kLogClamp);
  ImGui::SliderFloat("alpha max", &s.alphaMax, 1e-4f, 1.0f, "%.4f", kLogClamp);
  s.alphaMax = std::max(s.alphaMax, s.alphaMin);
  ImGui::SliderFloat("half-life (frames)", &s.halfLifeFrames, 0.0f, 200.0f,
                     s.halfLifeFrames > 0 ? "%.0f" : "never forget", kClamp);
  ImGui::SliderFloat("forget on light move", &s.forgetOnLightMove, 0.0f, 20.0f,
                     s.forgetOnLightMove > 0 ? "%.1f halvings/radius" : "off", kClamp);
  ImGui::SliderFloat("guided share", &s.selectProbability, 0.0f, 0.95f, "%.2f", kClamp);
  ImGui::Checkbox("learned light selection", &s.lightLearning);
  ImGui::SliderFloat("light mix", &s.lightMix, 0.0f, 0.95f, "%.2f", kClamp);
  r.changed = s.enabled != before.enabled || s.learn != before.learn || s.target != before.target ||
              s.rows != before.rows || s.cols != before.cols || s.alphaMin != before.alphaMin ||
              s.alphaMax != before.alphaMax || s.halfLifeFrames != before.halfLifeFrames ||
              s.forgetOnLightMove != before.forgetOnLightMove ||
              s.selectProbability != before.selectProbability ||
              s.lightLearning != before.lightLearning || s.lightMix != before.lightMix;
  r.regenerate = ImGui::Button("regenerate points");
  ImGui::Text("%u cache points (%u from camera paths)", st.points, st.spawnedPoints);
  ImGui::Text("%u strata, %u lights learned", st.strata, st.lightsLearned);
  ImGui::TextDisabled("rejection %.3f..%.3f, search %.3f", st.rejectionMin, st.rejectionMax,
                      st.searchRadius);
  return r;
}

}  // namespace qlight::game
