// qlight bench: what the learning buys and what it costs, at equal time and at
// equal samples, per scene, against a converged reference; writes bench.json,
// the final images, plots and a markdown report.
#pragma once
#include <functional>

#include "game/common_options.h"

namespace qlight::game {

std::function<int()> addBenchCommand(CLI::App& app, const CommonOptions& common);

}  // namespace qlight::game
