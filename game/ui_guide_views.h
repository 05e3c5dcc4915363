// Seeing the learning in the window: the cache points drawn over the image (coloured by
// learned irradiance or by confidence), and for the point under the cursor its learned Q as
// a disc of strata in false colour (Dahm & Keller's figure 5: the hemisphere seen from above,
// rows as equal-area rings, columns as wedges) with its learned light values as bars. The
// tables are read back a few times a second, so the views follow a moving light live.
#pragma once
#include <imgui.h>

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "engine/guiding/guide_inspection.h"
#include "engine/render/scene_draw.h"
#include "engine/session/renderer.h"

namespace qlight::game {

struct GuideViewSettings {
  bool pointsOverlay = false;
  bool colourByConfidence = false;  // else by learned irradiance (log scale)
  bool hemisphere = true;           // Q of the point under the cursor
};

// The panel's controls for the views (inside the Guiding section).
void drawGuideViewControls(GuideViewSettings& settings);

class GuideViews {
 public:
  GuideViewSettings settings;

  // Draws the enabled views for this frame: `camera` is what the image shows, `display` the
  // window size the image fills, `mouse` the cursor (ignored when `mouseFree` is false, i.e.
  // over the panel).
  void draw(session::Renderer& renderer, const render::CameraView& camera, ImVec2 display,
            ImVec2 mouse, bool mouseFree);
  // What the views showed last, for the demo's exit line (scripted runs check it); empty
  // when no view ran.
  std::string summary() const;

 private:
  using Clock = std::chrono::steady_clock;
  void refreshPoints(session::Renderer& renderer, const render::CameraView& camera);
  void refreshDetail(session::Renderer& renderer, const render::CameraView& camera, ImVec2 display,
                     ImVec2 mouse);

  std::vector<guiding::PointSummary> visible_;  // points the camera sees, at the last refresh
  std::optional<guiding::PointDetail> detail_;
  Clock::time_point pointsAt_{}, detailAt_{};
  size_t pointsDrawn_ = 0;  // in the last frame with the overlay
  bool drewPoints_ = false, drewDetail_ = false;
};

}  // namespace qlight::game
