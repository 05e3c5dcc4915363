// Options shared by the qlight subcommands, and their CLI11 wiring.
#pragma once
#include <CLI/CLI.hpp>
#include <string>

#include "engine/render/render_settings.h"

namespace qlight::game {

struct CommonOptions {
  std::string device;  // --device: pick a Vulkan device by name
  bool validation = false;
};

// Adds --width --height --seed --max-depth --estimator --rr --exposure --tonemap.
void addRenderOptions(CLI::App& app, render::RenderSettings& s);

// Exit code when the validation layer reported something (tests treat it as failure).
constexpr int kExitValidation = 3;

}  // namespace qlight::game
