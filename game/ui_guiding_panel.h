// The "Guiding" section of the demo panel: Q-learned importance sampling's
// settings, edited live (learning rate bounds, strata, selection probability,
// light learning), and what it has learned so far.
#pragma once
#include "engine/guiding/guiding_settings.h"
#include "engine/guiding/q_guide.h"

namespace qlight::game {

struct GuidingPanelResult {
  bool changed = false;     // settings edited
  bool regenerate = false;  // "regenerate points" pressed
};

GuidingPanelResult drawGuidingSection(guiding::GuidingSettings& settings,
                                      const guiding::GuidingStats& stats);

}  // namespace qlight::game
