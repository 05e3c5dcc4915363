// The settings file: every render, guiding and window setting as JSON, so that a run can be
// saved and replayed. {"render": {...}, "guiding": {...}, "window": {...}}; keys are the CLI
// option names in snake_case (max_depth, alpha_min), enums the CLI's words ("mis", "aces",
// "photon", "returns"), on|off options JSON booleans.
#pragma once
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "game/settings.h"

namespace qlight::game {

// True when a CLI option (e.g. "--exposure") was given on the command line: it overrides the
// file, which then leaves that setting alone.
using GivenOnCommandLine = std::function<bool(const std::string& option)>;

// Every setting, in the file's layout and order.
nlohmann::ordered_json settingsToJson(const Settings& s);

// Applies the keys of `json` to `s`. A key that is unknown, of the wrong type, out of range
// or refused by guiding::validate leaves its setting as it was and gives a warning naming it
// (`F: unknown key "guiding.alpha_mn" ignored`, F being `fileName`). Returns the warnings.
std::vector<std::string> applySettingsJson(const nlohmann::json& json, Settings& s,
                                           const std::string& fileName,
                                           const GivenOnCommandLine& given = {});

// Reads `file` and applies it as applySettingsJson does. Throws std::runtime_error, one line
// naming the file, when it cannot be read or is not a JSON object.
std::vector<std::string> loadSettingsFile(const std::filesystem::path& file, Settings& s,
                                          const GivenOnCommandLine& given = {});

// Writes every setting to `file` through a temporary file next to it and a rename, so that a
// reader never sees half a file. Throws std::runtime_error naming the file.
void saveSettingsFile(const std::filesystem::path& file, const Settings& s);

}  // namespace qlight::game
