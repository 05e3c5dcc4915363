#include "game/shipped_scenes.h"

#include <algorithm>
#include <filesystem>

namespace qlight::game {

namespace fs = std::filesystem;

namespace {
// The committed scenes, and those the build generates (too large for the repository).
const char* const kSceneFolders[] = {QLIGHT_ASSETS_DIR, QLIGHT_GENERATED_ASSETS_DIR};
}  // namespace

std::string resolveScene(const std::string& name) {
  if (fs::exists(name)) return name;
  for (const char* folder : kSceneFolders) {
    fs::path shipped = fs::path(folder) / name;
    if (fs::exists(shipped)) return shipped.string();
    if (fs::exists(shipped.string() + ".gltf")) return shipped.string() + ".gltf";
  }
  return name;
}

std::vector<std::string> shippedScenes() {
  std::vector<std::string> scenes;
  for (const char* folder : kSceneFolders) {
    if (!fs::is_directory(folder)) continue;
    for (const auto& entry : fs::directory_iterator(folder))
      if (entry.path().extension() == ".gltf") scenes.push_back(entry.path().string());
  }
  std::sort(scenes.begin(), scenes.end(), [](const std::string& a, const std::string& b) {
    return fs::path(a).filename() < fs::path(b).filename();
  });
  return scenes;
}

}  // namespace qlight::game
