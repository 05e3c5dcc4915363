// The user's environment light (--env, --sky, the settings file's "environment"): read from
// its file into the scene before the renderer starts, and what the user is told about the
// scene's lighting (the fallback sky, a black environment).
#pragma once
#include <optional>
#include <string>

#include "engine/scene/scene_asset.h"
#include "game/settings.h"

namespace qlight::game {

// "R,G,B": three finite numbers in [0, 1e6]; nullopt when the text is not that.
std::optional<glm::vec3> parseSkyColor(const std::string& text);

// The environment the settings choose (nullopt: none). Throws std::runtime_error, one line
// naming the file, when the map cannot be read or holds a texel that is not finite and
// non-negative.
std::optional<scene::EnvironmentAsset> loadEnvironment(const EnvironmentSettings& s);

// Puts the chosen environment into the scene (and leaves the scene alone without one).
void attachEnvironment(scene::SceneAsset& scene, const EnvironmentSettings& s);

// One line on stderr when the scene is lit by the fallback sky (it has no light, or only glow
// maps), or the chosen environment adds no light (it is black), as the renderer's GpuScene
// decided (RenderStats holds all three).
void reportSceneLighting(bool fallbackSky, bool glowMapsOnly, bool environmentLit,
                         const scene::SceneAsset& asset, const std::string& sceneName);

}  // namespace qlight::game
