// The bench's results for one scene, their headline ratios, and the output
// folder: bench.json with every figure, the final images as PFM, and the
// report and plots drawn from them by tools/bench_report.py (matplotlib).
#pragma once
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "game/bench/bench_methods.h"
#include "game/bench/bench_reference.h"

namespace qlight::game::bench {

struct SceneBench {
  std::string name;
  std::filesystem::path file;
  uint64_t triangles = 0;
  uint32_t lights = 0;
  Reference reference;
  std::vector<MethodResult> methods;  // methods[0] is unguided, the baseline
};

// The scene's entry of bench.json; writes its PFM images under `outDir`/images/<name>/.
nlohmann::json sceneJson(const SceneBench& scene, const std::filesystem::path& outDir);

// Runs tools/`scriptName` (python3 with matplotlib) on `outDir`. Throws with its message
// when it fails.
void runReportScript(const std::string& scriptName, const std::filesystem::path& outDir);
// Runs tools/bench_report.py on `outDir`.
void writeReport(const std::filesystem::path& outDir);

}  // namespace qlight::game::bench
