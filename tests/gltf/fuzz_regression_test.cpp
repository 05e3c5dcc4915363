// The glTF fuzzer's seeds (fuzz/corpus/gltf), the smallest of what it grew from them
// (fuzz/corpus/gltf-grown) and every input it ever crashed on
// (tests/data/gltf-fuzz, one file per defect, named after it) go through the
// loader as the fuzzer runs them: each gives a scene or one std::runtime_error
// line naming the input, never another exception. Under the sanitize preset a
// memory or undefined-behaviour error fails the run too.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <vector>

#include "engine/gltf/gltf_loader.h"

namespace qlight::gltf {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> inputs() {
  std::vector<fs::path> files;
  for (const char* dir : {"/fuzz/corpus/gltf", "/fuzz/corpus/gltf-grown", "/tests/data/gltf-fuzz"})
    for (const auto& e : fs::directory_iterator(std::string(QLIGHT_SOURCE_DIR) + dir))
      if (e.is_regular_file() && e.path().filename() != "README.md") files.push_back(e.path());
  return files;
}

TEST(GltfFuzzRegression, EveryInputLoadsOrFailsWithOneLine) {
  const std::vector<fs::path> files = inputs();
  ASSERT_GE(files.size(), 10u) << "the corpus is missing";
  const fs::path baseDir = fs::path(QLIGHT_SOURCE_DIR) / "fuzz/corpus/gltf";
  for (const fs::path& f : files) {
    std::ifstream in(f, std::ios::binary);
    std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                               std::istreambuf_iterator<char>());
    try {
      SceneAsset s = loadGltfFromMemory(bytes, baseDir, "input.gltf");
      (void)s;
    } catch (const std::runtime_error& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind("input.gltf: ", 0), 0u) << f << ": " << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << f << ": " << what;
    } catch (const std::exception& e) {
      ADD_FAILURE() << f << ": not a runtime_error: " << e.what();
    }
  }
}

}  // namespace
}  // namespace qlight::gltf
