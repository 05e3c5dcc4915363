#include "game/ui_panel.h"

#include <imgui.h>

#include <algorithm>

namespace qlight::game {

PanelChanges drawQlightPanel(const StatsView& stats, render::RenderSettings& settings,
                             float& renderScale, DynamicResolution& dynamic, SceneClock& clock,
                             FreeCamera& camera, const std::function<void()>& windowSection,
                             const std::function<void()>& guidingSection) {
  PanelChanges changes;
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  float height = std::min(ImGui::GetIO().DisplaySize.y - 16.0f, 640.0f);
  ImGui::SetNextWindowSize(ImVec2(330, std::max(height, 100.0f)), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(0.85f);
  if (ImGui::Begin("qlight")) {
    if (ImGui::CollapsingHeader("Stats", ImGuiTreeNodeFlags_DefaultOpen)) drawStatsSection(stats);
    if (ImGui::CollapsingHeader("Render", ImGuiTreeNodeFlags_DefaultOpen))
      changes.renderSettings = drawRenderSection(settings, renderScale, dynamic);
    if (guidingSection && ImGui::CollapsingHeader("Guiding", ImGuiTreeNodeFlags_DefaultOpen))
      guidingSection();
    if (ImGui::CollapsingHeader("Scene", ImGuiTreeNodeFlags_DefaultOpen))
      changes.scenePose = drawSceneSection(clock);
    if (ImGui::CollapsingHeader("Camera"))
      changes.resetCamera = drawCameraSection(camera, stats.cameraPath);
    if (windowSection && ImGui::CollapsingHeader("Window", ImGuiTreeNodeFlags_DefaultOpen))
      windowSection();
    ImGui::TextDisabled("WASD QE move, drag look, wheel speed, F1 UI, F9 path, F12 shot");
  }
  ImGui::End();
  return changes;
}

void drawStatsSection(const StatsView& v) {
  const FrameStats& s = *v.stats;
  ImGui::Text("%.1f ms/frame  %.1f FPS", s.frameMs(), s.fps());
  ImGui::Text("%u spp accumulated at %ux%u", v.accumulatedSpp, v.renderWidth, v.renderHeight);
  ImGui::Text("%.2f Mrays/s", s.mraysPerSecond());
  ImGui::Text("emitter hits %.1f%% of paths", 100.0 * s.emitterHitShare());
  ImGui::Text("mean path length %.2f vertices", s.meanPathLength());
  ImGui::Text("rejected samples (NaN/Inf) %llu", (unsigned long long)s.rejectedSamples());
  if (s.gpuMs().empty()) {
    ImGui::TextDisabled("GPU timings: no timestamps on this queue");
  } else if (ImGui::BeginTable("gpu", 2, ImGuiTableFlags_SizingStretchProp)) {
    for (auto& [name, ms] : s.gpuMs()) {
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(name.c_str());
      ImGui::TableNextColumn();
      ImGui::Text("%.2f ms", ms);
    }
    ImGui::TableNextColumn();
    ImGui::TextUnformatted("GPU total");
    ImGui::TableNextColumn();
    ImGui::Text("%.2f ms", s.gpuTotalMs());
    ImGui::EndTable();
  }
  ImGui::TextDisabled("%s", v.device.c_str());
}

bool drawRenderSection(render::RenderSettings& s, float& renderScale, DynamicResolution& dynamic) {
  bool changed = false;
  const char* estimators[] = {"MIS (NEE + BSDF)", "BSDF only", "NEE only"};
  int estimator = int(s.estimator);
  if (ImGui::Combo("estimator", &estimator, estimators, 3)) {
    s.estimator = render::Estimator(estimator);
    changed = true;
  }
  int depth = int(s.maxDepth);
  if (ImGui::SliderInt("max depth", &depth, 0, 32, "%d", ImGuiSliderFlags_AlwaysClamp))
    s.maxDepth = uint32_t(depth), changed = true;
  int spp = int(s.samplesPerFrame);
  if (ImGui::SliderInt("samples/frame", &spp, 1, 16, "%d", ImGuiSliderFlags_AlwaysClamp))
    s.samplesPerFrame = uint32_t(spp), changed = true;
  changed |= ImGui::Checkbox("Russian roulette", &s.russianRoulette);
  changed |= ImGui::SliderFloat("exposure", &s.exposure, 0.05f, 20.0f, "%.2f",
                                ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
  const char* tonemaps[] = {"clamp", "ACES"};
  int tonemap = int(s.tonemap);
  if (ImGui::Combo("tonemap", &tonemap, tonemaps, 2))
    s.tonemap = image::Tonemap(tonemap), changed = true;
  changed |= ImGui::SliderFloat("render scale", &renderScale, 0.1f, 1.0f, "%.2f",
                                ImGuiSliderFlags_AlwaysClamp);
  ImGui::Checkbox("dynamic resolution", &dynamic.enabled);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("while the camera moves, a smaller render holds the target frame time");
  if (dynamic.enabled)
    ImGui::SliderFloat("target frame", &dynamic.targetMs, 16.0f, 1000.0f, "%.0f ms",
                       ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
  ImGui::Text("scale now %.2f%s", dynamic.scale,
              dynamic.lowered(renderScale) ? " (lowered while moving)" : "");
  int seed = int(s.seed);
  if (ImGui::InputInt("seed", &seed)) s.seed = uint32_t(std::max(seed, 0)), changed = true;
  ImGui::SliderFloat("temporal blend", &s.temporalBlend, 0.0f, 0.95f, "%.2f",
                     ImGuiSliderFlags_AlwaysClamp);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("animated scenes: history kept when lights move (0: restart)");
  return changed;
}

bool drawSceneSection(SceneClock& clock) {
  if (!clock.animated()) {
    ImGui::TextDisabled("static scene (no animation)");
    return false;
  }
  if (ImGui::Button(clock.playing ? "pause" : "play")) clock.playing = !clock.playing;
  bool moved = ImGui::SliderFloat("time", &clock.time, 0.0f, clock.duration, "%.2f s",
                                  ImGuiSliderFlags_AlwaysClamp);
  ImGui::SliderFloat("speed", &clock.speed, 0.0f, 4.0f, "%.2fx", ImGuiSliderFlags_AlwaysClamp);
  return moved;
}

bool drawCameraSection(FreeCamera& camera, const std::string& pathStatus) {
  ImGui::SliderFloat("speed##camera", &camera.speed, 0.01f, 100.0f, "%.2f /s",
                     ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
  ImGui::Text("position %.2f %.2f %.2f", camera.position.x, camera.position.y, camera.position.z);
  ImGui::Text("yaw %.0f  pitch %.0f deg", camera.yaw * 57.2958f, camera.pitch * 57.2958f);
  if (!pathStatus.empty()) ImGui::TextUnformatted(pathStatus.c_str());
  return ImGui::Button("reset (R)");
}

}  // namespace qlight::game
