// `qlight render`: one image of a scene at a given time, with a stats file.
#pragma once
#include <functional>

#include "game/common_options.h"

namespace qlight::game {

// Registers the subcommand; the returned function runs it (exit code).
std::function<int()> addRenderCommand(CLI::App& app, const CommonOptions& common);

}  // namespace qlight::game
