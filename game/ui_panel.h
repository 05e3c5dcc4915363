// The demo window's ImGui panel "qlight": Stats, Render, Scene and Camera
// sections. Each section edits plain state and reports what changed; the
// window decides what that means for the renderer.
#pragma once
#include <functional>
#include <string>

#include "engine/render/render_settings.h"
#include "game/dynamic_resolution.h"
#include "game/window_camera.h"
#include "game/window_scene.h"
#include "game/window_stats.h"

namespace qlight::game {

struct StatsView {
  const FrameStats* stats = nullptr;
  uint32_t accumulatedSpp = 0;
  uint32_t renderWidth = 0, renderHeight = 0;
  std::string device;
  std::string cameraPath;  // the Camera section's line on path recording or playback
};

struct PanelChanges {
  bool renderSettings = false;  // `settings` or `renderScale` edited
  bool scenePose = false;       // the time slider moved
  bool resetCamera = false;
};

// Draws the whole panel; returns what the user changed this frame.
// `windowSection` draws the Window section (vsync, the settings file), `guidingSection` the
// Guiding section (it owns the learned state).
PanelChanges drawQlightPanel(const StatsView& stats, render::RenderSettings& settings,
                             float& renderScale, DynamicResolution& dynamic, SceneClock& clock,
                             FreeCamera& camera, const std::function<void()>& windowSection = {},
                             const std::function<void()>& guidingSection = {});

void drawStatsSection(const StatsView& view);
bool drawRenderSection(render::RenderSettings& settings, float& renderScale,
                       DynamicResolution& dynamic);
bool drawSceneSection(SceneClock& clock);  // true: the pose changed
// true: reset requested. `pathStatus`: the camera path's recording or playback.
bool drawCameraSection(FreeCamera& camera, const std::string& pathStatus = {});

}  // namespace qlight::game
