#include "game/shipped_scenes.h"

#include <algorithm>
#include <filesystem>

namespace qlight::game {

namespace fs = std::filesystem;

std::string resolveScene(const std::string& name) {
  if (fs::exists(name)) return name;
  fs::path shipped = fs::path(QLIGHT_ASSETS_DIR) / name;
  if (fs::exists(shipped)) return shipped.string();
  if (fs::exists(shipped.string() + ".gltf")) return shipped.string() + ".gltf";
  return name;
}

std::vector<std::string> shippedScenes() {
  std::vector<std::string> scenes;
  for (const auto& entry : fs::directory_iterator(QLIGHT_ASSETS_DIR))
    if (entry.path().extension() == ".gltf") scenes.push_back(entry.path().string());
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

}  // namespace qlight::game
