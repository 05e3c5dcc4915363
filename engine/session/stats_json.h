// The stats file of a render: what was rendered, how fast, and the measures
// the papers use (emitter hit share, mean path length).
#pragma once
#include <filesystem>
#include <nlohmann/json.hpp>

#include "engine/session/offline_render.h"

namespace qlight::session {

nlohmann::json statsToJson(const RenderStats& stats);
void writeJson(const std::filesystem::path& path, const nlohmann::json& json);

}  // namespace qlight::session
