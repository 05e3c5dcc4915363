// The panel's Display section: temporal reuse while moving and the denoiser (display only).
#pragma once
#include "engine/ui/display_filter.h"

namespace qlight::game {

void drawDisplayFilterSection(ui::DisplayFilterSettings& settings);

}  // namespace qlight::game
