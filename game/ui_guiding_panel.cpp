#include "game/ui_guiding_panel.h"

#include <imgui.h>

#include <algorithm>

#include "shaders/shared/dqn.h"
#include "shaders/shared/strata.h"

namespace qlight::game {
namespace {
// Typed values (ctrl+click) stay in range too: an alpha-min of 0 must not reach the guide.
constexpr ImGuiSliderFlags kClamp = ImGuiSliderFlags_AlwaysClamp;
constexpr ImGuiSliderFlags kLogClamp = ImGuiSliderFlags_Logarithmic | kClamp;

// The deep Q network's shape (a new network when it changes) and its training.
void drawNetworkSettings(guiding::GuidingSettings& s) {
  int width = int(s.dqnWidth) / 4, layers = int(s.dqnHidden), bins = int(s.dqnBins);
  int batch = int(s.dqnBatch), interval = int(s.dqnTargetInterval), steps = int(s.dqnStepsPerFrame);
  int grid = int(s.dqnGrid);
  ImGui::SliderInt("network width", &width, 1, int(shared::kDqnMaxWidth) / 4, "", kClamp);
  ImGui::SameLine();
  ImGui::Text("%d neurons", 4 * width);
  ImGui::SliderInt("hidden layers", &layers, 1, int(shared::kDqnMaxHidden), "%d", kClamp);
  ImGui::SliderInt("one-blob bins", &bins, 1, int(shared::kDqnMaxBins), "%d", kClamp);
  ImGui::SliderInt("batch", &batch, 64, 16384, "%d", ImGuiSliderFlags_Logarithmic | kClamp);
  ImGui::SliderInt("steps per frame", &steps, 0, 8, "%d", kClamp);
  ImGui::SliderFloat("network learning rate", &s.dqnLearningRate, 1e-5f, 1e-1f, "%.5f", kLogClamp);
  ImGui::SliderInt("target interval", &interval, 1, 64, "%d frames", kClamp);
  // The paths evaluate the network at every vertex (0), or read the cell of a grid it is baked
  // into.
  ImGui::SliderInt("baked grid", &grid, 0, int(shared::kDqnMaxGrid), grid == 0 ? "off" : "%d cells",
                   kClamp);
  s.dqnWidth = uint32_t(4 * width);
  s.dqnHidden = uint32_t(layers);
  s.dqnBins = uint32_t(bins);
  s.dqnBatch = uint32_t(batch);
  s.dqnStepsPerFrame = uint32_t(steps);
  s.dqnTargetInterval = uint32_t(interval);
  s.dqnGrid = grid == 1 ? 2u : uint32_t(grid);
}

bool networkChanged(const guiding::GuidingSettings& a, const guiding::GuidingSettings& b) {
  return a.dqnWidth != b.dqnWidth || a.dqnHidden != b.dqnHidden || a.dqnBins != b.dqnBins ||
         a.dqnBatch != b.dqnBatch || a.dqnStepsPerFrame != b.dqnStepsPerFrame ||
         a.dqnLearningRate != b.dqnLearningRate || a.dqnTargetInterval != b.dqnTargetInterval ||
         a.dqnGrid != b.dqnGrid;
}

}  // namespace

GuidingPanelResult drawGuidingSection(guiding::GuidingSettings& s,
                                      const guiding::GuidingStats& st) {
  GuidingPanelResult r;
  guiding::GuidingSettings before = s;
  ImGui::Checkbox("guided sampling", &s.enabled);
  ImGui::SameLine();
  int method = s.method == guiding::GuideMethod::Dqn ? 1 : 0;
  ImGui::Combo("##method", &method, "Q tables\0deep Q network\0");
  s.method = method == 1 ? guiding::GuideMethod::Dqn : guiding::GuideMethod::Q;
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
  const int maxStrata =
      int(s.method == guiding::GuideMethod::Dqn ? shared::kDqnMaxOutputs : shared::kMaxStrata);
  s.cols = uint32_t(std::max(1, std::min(cols, maxStrata / rows)));  // R x C <= the maximum
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
  ImGui::SliderFloat("NEE where blocked", &s.neeMinProbability, 0.01f, 1.0f,
                     s.neeMinProbability < 1 ? "%.2f" : "always", kLogClamp);
  ImGui::Checkbox("roulette by expected light", &s.guidedRoulette);  // else by throughput
  if (s.method == guiding::GuideMethod::Dqn) drawNetworkSettings(s);
  r.changed = s.enabled != before.enabled || s.method != before.method ||
              networkChanged(s, before) || s.learn != before.learn || s.target != before.target ||
              s.rows != before.rows || s.cols != before.cols || s.alphaMin != before.alphaMin ||
              s.alphaMax != before.alphaMax || s.halfLifeFrames != before.halfLifeFrames ||
              s.forgetOnLightMove != before.forgetOnLightMove ||
              s.selectProbability != before.selectProbability ||
              s.lightLearning != before.lightLearning || s.lightMix != before.lightMix ||
              s.neeMinProbability != before.neeMinProbability ||
              s.guidedRoulette != before.guidedRoulette;
  r.regenerate = ImGui::Button("regenerate points");
  ImGui::Text("%u cache points (%u from camera paths)", st.points, st.spawnedPoints);
  ImGui::Text("%u strata, %u lights learned", st.strata, st.lightsLearned);
  ImGui::TextDisabled("rejection %.3f..%.3f, search %.3f", st.rejectionMin, st.rejectionMax,
                      st.searchRadius);
  return r;
}

}  // namespace qlight::game
