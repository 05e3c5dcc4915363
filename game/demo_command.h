// `qlight demo`: the flythrough. With a display it opens a window with the UI;
// without one (or with --headless) it renders the same timeline to images and a
// stats file.
#pragma once
#include <CLI/CLI.hpp>
#include <functional>

#include "game/cli_options.h"

namespace qlight::game {

// The demo's tracking: learned values and confidence halve in this many frames without
// new data (measured by `qlight bench --tracking`, docs/tracking.md).
constexpr float kDemoHalfLifeFrames = 8.0f;

std::function<int()> addDemoCommand(CLI::App& app, const CommonOptions& common);

}  // namespace qlight::game
