// libFuzzer target for the glTF import path: JSON and GLB containers, buffers,
// buffer views and accessors, images, materials, meshes, nodes, cameras,
// lights and animations (gltf::loadGltfFromMemory, what loadGltf runs after
// reading the file). The loader's contract is a SceneAsset or one
// std::runtime_error line; anything else (another exception, a sanitizer
// report, a crash, a hang) is a defect. Regressions: tests/gltf/fuzz_regression_test.cpp.
#include <cstddef>
#include <cstdint>
#include <stdexcept>

#include "engine/gltf/gltf_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    qlight::gltf::loadGltfFromMemory({data, size}, QLIGHT_FUZZ_BASE_DIR, "input.gltf");
  } catch (const std::runtime_error&) {
    // The documented refusal.
  }
  return 0;
}
