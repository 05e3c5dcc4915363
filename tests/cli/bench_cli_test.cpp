// `qlight bench` as a user runs it: the quick mode writes its report, JSON and
// plots with every figure finite (not their values: speed is a benchmark's
// business, not a test's), and bad input gets one line and a non-zero exit.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/cli/run_binary.h"

namespace qlight::test {
namespace {

namespace fs = std::filesystem;

// Paths of every number that is not finite (JSON null where a number belongs).
void collectMissing(const nlohmann::json& j, const std::string& path,
                    std::vector<std::string>& missing) {
  if (j.is_null())
    missing.push_back(path);
  else if (j.is_number_float() && !std::isfinite(j.get<double>()))
    missing.push_back(path);
  else if (j.is_object())
    for (auto& [key, value] : j.items()) collectMissing(value, path + "/" + key, missing);
  else if (j.is_array())
    for (size_t i = 0; i < j.size(); ++i)
      collectMissing(j[i], path + "/" + std::to_string(i), missing);
}

TEST(BenchCli, QuickModeWritesReportJsonAndPlotsWithFiniteFigures) {
  fs::path dir = tempDir("bench");
  auto r = runQlight("bench --quick --scene cornell_box --budget 1 --reference-spp 16 --out " +
                     (dir / "out").string() + " --cache " + (dir / "cache").string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  for (const char* file : {"report.md", "bench.json", "plots/cornell_box_relmse_time.png",
                           "plots/cornell_box_relmse_spp.png", "plots/cornell_box_emitter_hits.png",
                           "plots/cornell_box_gpu_passes.png", "plots/cornell_box_images.png",
                           "images/cornell_box/reference.pfm", "images/cornell_box/guided.pfm"}) {
    ASSERT_TRUE(fs::exists(dir / "out" / file)) << file;
    EXPECT_GT(fs::file_size(dir / "out" / file), 0u) << file;
  }
  nlohmann::json j = nlohmann::json::parse(std::ifstream(dir / "out" / "bench.json"));
  j.erase("traversal");  // measured by bench_embree, not the quick mode
  // Left out (null) by design while the reference's noise is over half unguided's error,
  // as it is with a 16 spp reference.
  for (auto& scene : j["scenes"])
    scene["headline"].erase("equal_spp_relmse_ratio_without_reference_noise");
  std::vector<std::string> missing;
  collectMissing(j, "", missing);
  EXPECT_TRUE(missing.empty()) << missing.front();
  ASSERT_EQ(j["scenes"].size(), 1u);
  ASSERT_EQ(j["scenes"][0]["methods"].size(), 5u);
  EXPECT_EQ(j["scenes"][0]["methods"][4]["name"], "guided_dqn");

  // A second run finds the reference in the cache.
  auto again = runQlight(
      "bench --quick --scene cornell_box --budget 0.2 --reference-spp 16 --no-report --out " +
      (dir / "out2").string() + " --cache " + (dir / "cache").string());
  ASSERT_EQ(again.exitCode, 0) << again.output;
  nlohmann::json k = nlohmann::json::parse(std::ifstream(dir / "out2" / "bench.json"));
  EXPECT_TRUE(k["scenes"][0]["reference"]["cached"].get<bool>());
}

TEST(BenchCli, BadInputIsAOneLineError) {
  fs::path dir = tempDir("bench_bad");
  const std::string out = " --out " + (dir / "o").string();
  for (std::string bad : {"--scene /nonexistent/scene.gltf" + out, "--budget 0" + out,
                          "--budget -2" + out, std::string("--out /proc/qlight_cannot_write")}) {
    auto r = runQlight("bench --quick --scene cornell_box " + bad);
    EXPECT_NE(r.exitCode, 0) << bad << "\n" << r.output;
    EXPECT_NE(r.output.find("qlight: error: bench:"), std::string::npos) << bad << "\n" << r.output;
  }
}

}  // namespace
}  // namespace qlight::test
