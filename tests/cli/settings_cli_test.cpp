// `--settings FILE` as a user runs it: a malformed file is a one-line error, unknown keys
// and wrong types warn by name while the rest applies, and options on the command line
// override the file (checked through the stats that `render` writes).
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/cli/run_binary.h"

namespace qlight::test {
namespace {

namespace fs = std::filesystem;

nlohmann::json readJson(const fs::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

void write(const fs::path& file, const std::string& text) { std::ofstream(file) << text; }

// A tiny render with `options`; its stats in dir/s.json.
RunResult renderWith(const fs::path& dir, const std::string& options) {
  return runQlight("render --scene " + asset("cornell_box.gltf") +
                   " --width 16 --height 16 --spp 1 --out " + (dir / "i.png").string() +
                   " --stats-json " + (dir / "s.json").string() + " " + options);
}

TEST(SettingsCli, MalformedFileIsOneLineErrorAndNonZeroExit) {
  fs::path dir = tempDir("settings_bad");
  const fs::path file = dir / "bad.json";
  write(file, "this is not JSON\n");
  RunResult r = renderWith(dir, "--settings " + file.string());
  EXPECT_NE(r.exitCode, 0) << r.output;
  std::istringstream lines(r.output);
  std::string line, only;
  int count = 0;
  while (std::getline(lines, line))
    if (!line.empty()) only = line, ++count;
  EXPECT_EQ(count, 1) << r.output;
  EXPECT_EQ(only.rfind("qlight: error: " + file.string() + ": not valid JSON: ", 0), 0u)
      << r.output;
  EXPECT_NE(only.find("line 1, column"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir / "i.png"));
}

TEST(SettingsCli, UnknownKeyAndWrongTypeWarnWhileValidKeysApply) {
  fs::path dir = tempDir("settings_warn");
  const fs::path file = dir / "settings.json";
  write(file, R"({"render": {"seed": 11, "max_depth": "deep", "estimator": "nee"},
                  "guiding": {"alpha_mn": 0.2, "alpha_min": 0.02, "strata": "4x2"}})");
  RunResult r = renderWith(dir, "--settings " + file.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const std::string prefix = "qlight: warning: " + file.string() + ": ";
  EXPECT_NE(r.output.find(prefix + "unknown key \"guiding.alpha_mn\" ignored"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find(prefix + "\"render.max_depth\" must be a whole number"),
            std::string::npos)
      << r.output;
  nlohmann::json stats = readJson(dir / "s.json");
  EXPECT_EQ(stats["seed"], 11);
  EXPECT_EQ(stats["max_depth"], 8);  // the default: the file's value was refused
  EXPECT_EQ(stats["estimator"], "nee");
  EXPECT_FLOAT_EQ(stats["alpha_min"].get<float>(), 0.02f);
  EXPECT_EQ(stats["strata"], "4x2");
}

TEST(SettingsCli, CommandLineOverridesTheFile) {
  fs::path dir = tempDir("settings_override");
  const fs::path file = dir / "settings.json";
  write(file, R"({"render": {"seed": 11, "max_depth": 3, "estimator": "nee", "width": 8},
                  "guiding": {"strata": "4x2", "alpha_min": 0.02}})");
  RunResult r = renderWith(dir, "--settings " + file.string() + " --seed 5 --strata 2x2");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(r.output.find("warning"), std::string::npos) << r.output;
  nlohmann::json stats = readJson(dir / "s.json");
  EXPECT_EQ(stats["seed"], 5);        // the command line's
  EXPECT_EQ(stats["strata"], "2x2");  // the command line's
  EXPECT_EQ(stats["width"], 16);      // the command line's
  EXPECT_EQ(stats["max_depth"], 3);   // the file's
  EXPECT_EQ(stats["estimator"], "nee");
  EXPECT_FLOAT_EQ(stats["alpha_min"].get<float>(), 0.02f);
}

// After the file, the command line's checks apply: bounds the file and an option cross.
TEST(SettingsCli, FileValueThatTheCommandLineMakesInvalidIsRefusedByName) {
  fs::path dir = tempDir("settings_cross");
  const fs::path file = dir / "settings.json";
  write(file, R"({"guiding": {"alpha_min": 0.5}})");
  RunResult r = renderWith(dir, "--settings " + file.string() + " --alpha-max 0.1");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("\"guiding.alpha_min\" 0.5: learning rate bounds"), std::string::npos)
      << r.output;
  nlohmann::json stats = readJson(dir / "s.json");
  EXPECT_FLOAT_EQ(stats["alpha_max"].get<float>(), 0.1f);
  EXPECT_LT(stats["alpha_min"].get<float>(), 0.1f);
}

TEST(SettingsCli, HeadlessDemoTakesTheFile) {
  fs::path dir = tempDir("settings_demo");
  const fs::path file = dir / "settings.json";
  write(file, R"({"render": {"width": 24, "height": 12}, "window": {"render_scale": 0.3}})");
  RunResult r = runQlight("demo --headless --frames 1 --out " + dir.string() + " --settings " +
                          file.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  nlohmann::json stats = readJson(dir / "stats.json");
  EXPECT_EQ(stats["width"], 24);
  EXPECT_EQ(stats["height"], 12);
}

}  // namespace
}  // namespace qlight::test
