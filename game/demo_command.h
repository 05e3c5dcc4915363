// `qlight demo`: the flythrough. With a display it opens a window with the UI;
// without one (or with --headless) it renders the same timeline to images and a
// stats file.
#pragma once
#include <functional>

#include "game/common_options.h"

namespace qlight::game {

// The demo's tracking (measured by `qlight bench --tracking`, README "Tracking moving
// lights"): what each point learned halves this many times per scene radius a light moves,
// and in this many frames without new data (0: not by time).
constexpr float kDemoForgetOnLightMove = 4.0f;
constexpr float kDemoHalfLifeFrames = 0.0f;

std::function<int()> addDemoCommand(CLI::App& app, const CommonOptions& common);

}  // namespace qlight::game
