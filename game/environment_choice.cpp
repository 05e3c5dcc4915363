#include "game/environment_choice.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "engine/render/environment_file.h"
#include "game/setting_words.h"

namespace qlight::game {

std::optional<glm::vec3> parseSkyColor(const std::string& text) {
  glm::vec3 c(0.0f);
  const char* p = text.c_str();
  for (int i = 0; i < 3; ++i) {
    char* end = nullptr;
    const float v = std::strtof(p, &end);
    if (end == p || !std::isfinite(v) || v < ranges::kSkyRadiance.lowest ||
        v > ranges::kSkyRadiance.highest)
      return std::nullopt;
    c[i] = v;
    p = end;
    if (i < 2 && *p++ != ',') return std::nullopt;
  }
  if (*p != '\0') return std::nullopt;
  return c;
}

std::optional<scene::EnvironmentAsset> loadEnvironment(const EnvironmentSettings& s) {
  if (!s.chosen()) return std::nullopt;
  scene::EnvironmentAsset env;
  if (!s.file.empty())
    env = render::loadEnvironmentMap(s.file);
  else
    env.color = *s.sky;
  env.strength = s.strength;
  env.rotationDegrees = s.rotationDegrees;
  return env;
}

void attachEnvironment(scene::SceneAsset& scene, const EnvironmentSettings& s) {
  scene.environment = loadEnvironment(s);
}

void reportSceneLighting(bool fallbackSky, bool glowMapsOnly, bool environmentLit,
                         const scene::SceneAsset& asset, const std::string& sceneName) {
  if (fallbackSky && glowMapsOnly)
    std::fprintf(stderr,
                 "qlight: warning: %s is lit only by emissive textures (glow maps): lit by a "
                 "uniform white sky as well (the fallback; --env or --sky choose the lighting, "
                 "--sky 0,0,0 none)\n",
                 sceneName.c_str());
  else if (fallbackSky)
    std::fprintf(stderr,
                 "qlight: warning: %s has no light: lit by a uniform white sky (the fallback; "
                 "--env or --sky choose the lighting)\n",
                 sceneName.c_str());
  else if (asset.environment && !environmentLit)
    std::fprintf(stderr, "qlight: warning: the environment%s%s is black: it adds no light\n",
                 asset.environment->name.empty() ? "" : " ", asset.environment->name.c_str());
}

}  // namespace qlight::game
