// Options shared by the qlight subcommands, and their CLI11 wiring.
#pragma once
#include <CLI/CLI.hpp>
#include <string>

#include "engine/guiding/guiding_settings.h"
#include "engine/render/render_settings.h"
#include "game/common_options.h"
#include "game/setting_words.h"
#include "game/settings.h"

namespace qlight::game {

// Adds --width --height, the tracing options, --exposure --temporal-blend --tonemap.
void addRenderOptions(CLI::App& app, render::RenderSettings& s);
// Adds what changes the traced image: --seed --max-depth --estimator --rr.
void addTracingOptions(CLI::App& app, render::RenderSettings& s);

// Adds --guiding --strata --alpha-min --alpha-max --points --light-learning
// --select-probability --point-set --nee. `strata` and `nee` are applied by
// finishGuidingOptions after parsing.
void addGuidingOptions(CLI::App& app, guiding::GuidingSettings& g, GuidingCli& cli);
void finishGuidingOptions(const GuidingCli& cli, guiding::GuidingSettings& g,
                          render::RenderSettings& r);

// CLI::Range for real numbers that also refuses NaN and infinities (CLI11's range check
// lets NaN through: every comparison with it is false).
CLI::Validator finiteRange(double lowest, double highest);
CLI::Validator finiteRange(Range range);
CLI::Validator wholeRange(Range range);  // integers within the range

// Adds --env FILE, --sky R,G,B (exclusive), --env-strength S, --env-rotation DEG.
// `skyText` holds --sky's text until finishEnvironmentOptions parses it.
void addEnvironmentOptions(CLI::App& app, EnvironmentSettings& env, std::string& skyText);
// After the settings file: --sky's colour, and a map or sky given on the command line replaces
// both of the file's ("file" and "sky").
void finishEnvironmentOptions(const CLI::App& cmd, const std::string& skyText,
                              EnvironmentSettings& env);

// Adds --settings FILE (game/settings_file.h).
void addSettingsOption(CLI::App& app, std::string& file);
// After parsing: applies the settings file, when one was given, to the settings whose
// options were not given on `cmd`'s command line, and prints its warnings. Throws
// std::runtime_error (one line naming the file) when it cannot be read or parsed.
void applySettingsFile(const CLI::App& cmd, const std::string& file, Settings& s);

}  // namespace qlight::game
