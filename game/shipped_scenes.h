// The scenes qlight ships (assets/, and the large ones the build generates into
// build/assets), found by name from any working directory.
#pragma once
#include <string>
#include <vector>

namespace qlight::game {

// A scene name resolves against the working directory, then the shipped assets (with or
// without ".gltf"); otherwise it is returned as given (the loader reports it missing).
std::string resolveScene(const std::string& name);

// Every shipped .gltf, sorted by name.
std::vector<std::string> shippedScenes();

}  // namespace qlight::game
