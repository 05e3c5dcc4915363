// The settings file as a library: every setting survives a save and a load, unknown keys,
// wrong types, out-of-range and invalid guiding values warn by name and leave the rest to
// apply, options given on the command line win, malformed files are one-line errors.
#include "game/settings_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "tests/support/temp_dir.h"

namespace qlight::game {
namespace {

namespace fs = std::filesystem;

fs::path tempDir() {
  const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  fs::path dir = test::processTempDir("settings_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write(const fs::path& file, const std::string& text) { std::ofstream(file) << text; }

// Every field away from its default (and from any other field's value where that is easy).
Settings everyFieldChanged() {
  Settings s;
  s.render.width = 641;
  s.render.height = 359;
  s.render.samplesPerFrame = 3;
  s.render.maxDepth = 5;
  s.render.seed = 4000000000u;
  s.render.estimator = render::Estimator::NeeOnly;
  s.render.russianRoulette = false;
  s.render.exposure = 2.7f;
  s.render.temporalBlend = 0.35f;
  s.render.tonemap = image::Tonemap::Clamp;
  s.guiding.enabled = false;
  s.guiding.rows = 16;
  s.guiding.cols = 4;
  s.guiding.alphaMin = 0.0123f;
  s.guiding.alphaMax = 0.75f;
  s.guiding.halfLifeFrames = 33.3f;
  s.guiding.forgetOnLightMove = 2.5f;
  s.guiding.selectProbability = 0.61f;
  s.guiding.confidenceUpdates = 7.5f;
  s.guiding.pointBudget = 5000;
  s.guiding.pointSet = guiding::PointSet::PoissonAo;
  s.guiding.target = guiding::LearningTarget::TdStep;
  s.guiding.lightLearning = false;
  s.guiding.lightMix = 0.3f;
  s.guiding.learn = false;
  s.window.renderScale = 0.65f;
  s.window.targetFrameMs = 42.5f;
  s.window.vsync = true;
  s.environment.file = "maps/sky.hdr";
  s.environment.sky = glm::vec3(0.25f, 0.5f, 2.0f);
  s.environment.strength = 3.5f;
  s.environment.rotationDegrees = -75.0f;
  return s;
}

void expectSameRender(const render::RenderSettings& a, const render::RenderSettings& b) {
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  EXPECT_EQ(a.samplesPerFrame, b.samplesPerFrame);
  EXPECT_EQ(a.maxDepth, b.maxDepth);
  EXPECT_EQ(a.seed, b.seed);
  EXPECT_EQ(a.estimator, b.estimator);
  EXPECT_EQ(a.russianRoulette, b.russianRoulette);
  EXPECT_EQ(a.exposure, b.exposure);
  EXPECT_EQ(a.temporalBlend, b.temporalBlend);
  EXPECT_EQ(a.tonemap, b.tonemap);
}

void expectSameGuiding(const guiding::GuidingSettings& a, const guiding::GuidingSettings& b) {
  EXPECT_EQ(a.enabled, b.enabled);
  EXPECT_EQ(a.rows, b.rows);
  EXPECT_EQ(a.cols, b.cols);
  EXPECT_EQ(a.alphaMin, b.alphaMin);
  EXPECT_EQ(a.alphaMax, b.alphaMax);
  EXPECT_EQ(a.halfLifeFrames, b.halfLifeFrames);
  EXPECT_EQ(a.forgetOnLightMove, b.forgetOnLightMove);
  EXPECT_EQ(a.selectProbability, b.selectProbability);
  EXPECT_EQ(a.confidenceUpdates, b.confidenceUpdates);
  EXPECT_EQ(a.pointBudget, b.pointBudget);
  EXPECT_EQ(a.pointSet, b.pointSet);
  EXPECT_EQ(a.target, b.target);
  EXPECT_EQ(a.lightLearning, b.lightLearning);
  EXPECT_EQ(a.lightMix, b.lightMix);
  EXPECT_EQ(a.learn, b.learn);
}

void expectSame(const Settings& a, const Settings& b) {
  expectSameRender(a.render, b.render);
  expectSameGuiding(a.guiding, b.guiding);
  EXPECT_EQ(a.window.renderScale, b.window.renderScale);
  EXPECT_EQ(a.window.targetFrameMs, b.window.targetFrameMs);
  EXPECT_EQ(a.window.vsync, b.window.vsync);
  EXPECT_EQ(a.environment.file, b.environment.file);
  EXPECT_EQ(a.environment.sky, b.environment.sky);
  EXPECT_EQ(a.environment.strength, b.environment.strength);
  EXPECT_EQ(a.environment.rotationDegrees, b.environment.rotationDegrees);
}

bool mentions(const std::vector<std::string>& warnings, const std::string& text) {
  for (const std::string& w : warnings)
    if (w.find(text) != std::string::npos) return true;
  return false;
}

std::string joined(const std::vector<std::string>& warnings) {
  std::string all;
  for (const std::string& w : warnings) all += w + "\n";
  return all;
}

TEST(SettingsFile, RoundTripKeepsEveryField) {
  fs::path file = tempDir() / "all.json";
  const Settings saved = everyFieldChanged();
  saveSettingsFile(file, saved);
  Settings loaded;  // defaults: every field differs from `saved`
  std::vector<std::string> warnings = loadSettingsFile(file, loaded);
  EXPECT_TRUE(warnings.empty()) << joined(warnings);
  expectSame(loaded, saved);
}

// The file is readable: CLI words, snake_case keys, short decimals.
TEST(SettingsFile, WritesCliWordsAndShortNumbers) {
  nlohmann::ordered_json j = settingsToJson(everyFieldChanged());
  EXPECT_EQ(j["render"]["estimator"], "nee");
  EXPECT_EQ(j["render"]["tonemap"], "clamp");
  EXPECT_EQ(j["render"]["rr"], false);
  EXPECT_EQ(j["guiding"]["strata"], "16x4");
  EXPECT_EQ(j["guiding"]["point_set"], "poisson");
  EXPECT_EQ(j["guiding"]["learning_target"], "td");
  EXPECT_EQ(j["window"]["vsync"], true);
  EXPECT_EQ(j["render"]["exposure"].dump(), "2.7");
  EXPECT_EQ(settingsToJson(Settings{}).dump().find("0.69999"), std::string::npos);
}

// Saving goes through a temporary file and a rename: the old file is replaced whole and
// nothing is left next to it.
TEST(SettingsFile, SaveReplacesTheFileAndLeavesNoTemporary) {
  fs::path dir = tempDir();
  write(dir / "s.json", "old contents");
  saveSettingsFile(dir / "s.json", everyFieldChanged());
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  Settings loaded;
  EXPECT_TRUE(loadSettingsFile(dir / "s.json", loaded).empty());
  EXPECT_EQ(loaded.render.width, 641u);
  EXPECT_THROW(saveSettingsFile(dir / "missing_dir" / "s.json", Settings{}), std::runtime_error);
}

TEST(SettingsFile, UnknownKeysAndWrongTypesWarnByNameAndTheRestApplies) {
  fs::path file = tempDir() / "mixed.json";
  write(file, R"({"render": {"seed": 7, "max_depth": "three", "estimator": "BSDF"},
                  "guiding": {"alpha_mn": 0.1, "alpha_min": 0.01, "light_learning": 1},
                  "window": {"vsync": true}, "extra": {}})");
  Settings s;
  std::vector<std::string> warnings = loadSettingsFile(file, s);
  const std::string name = file.string();
  EXPECT_TRUE(mentions(warnings, name + ": unknown key \"guiding.alpha_mn\" ignored"))
      << joined(warnings);
  EXPECT_TRUE(mentions(warnings, "unknown key \"extra\"")) << joined(warnings);
  EXPECT_TRUE(mentions(warnings, "\"render.max_depth\" must be a whole number"))
      << joined(warnings);
  EXPECT_TRUE(mentions(warnings, "\"guiding.light_learning\" must be true or false"))
      << joined(warnings);
  EXPECT_EQ(warnings.size(), 4u) << joined(warnings);
  for (const std::string& w : warnings) EXPECT_EQ(w.find('\n'), std::string::npos) << w;
  EXPECT_EQ(s.render.seed, 7u);
  EXPECT_EQ(s.render.estimator, render::Estimator::BsdfOnly);  // any case, as on the CLI
  EXPECT_EQ(s.guiding.alphaMin, 0.01f);
  EXPECT_TRUE(s.window.vsync);
  EXPECT_EQ(s.render.maxDepth, Settings{}.render.maxDepth);
  EXPECT_EQ(s.guiding.lightLearning, Settings{}.guiding.lightLearning);
}

// The CLI's ranges and guiding::validate: a refused value names its key and is not applied.
TEST(SettingsFile, OutOfRangeAndInvalidValuesAreNotApplied) {
  Settings s;
  std::vector<std::string> warnings = applySettingsJson(
      nlohmann::json::parse(R"({"render": {"width": 0, "exposure": 1e9, "tonemap": "filmic",
                                           "temporal_blend": 0.5},
                                "guiding": {"strata": "40x40", "select_probability": 0.99,
                                            "half_life": -1, "points": 64},
                                "window": {"render_scale": 2}})"),
      s, "f.json");
  for (const char* key : {"render.width", "render.exposure", "render.tonemap", "guiding.strata",
                          "guiding.select_probability", "guiding.half_life", "window.render_scale"})
    EXPECT_TRUE(mentions(warnings, std::string("\"") + key + "\"")) << key << "\n"
                                                                    << joined(warnings);
  EXPECT_EQ(warnings.size(), 7u) << joined(warnings);
  const Settings defaults;
  EXPECT_EQ(s.render.width, defaults.render.width);
  EXPECT_EQ(s.render.exposure, defaults.render.exposure);
  EXPECT_EQ(s.guiding.rows, defaults.guiding.rows);
  EXPECT_EQ(s.guiding.selectProbability, defaults.guiding.selectProbability);
  EXPECT_EQ(s.window.renderScale, defaults.window.renderScale);
  EXPECT_EQ(s.render.temporalBlend, 0.5f);
  EXPECT_EQ(s.guiding.pointBudget, 64u);
  EXPECT_NO_THROW(guiding::validate(s.guiding));
}

// Bounds that are valid together apply whatever the settings before them (no order of
// keys may refuse them); bounds crossed within the file refuse one of them, named.
TEST(SettingsFile, GuidingValuesAreValidatedTogether) {
  Settings s;
  s.guiding.alphaMin = 0.1f;
  s.guiding.alphaMax = 0.2f;
  EXPECT_TRUE(applySettingsJson(
                  nlohmann::json::parse(R"({"guiding": {"alpha_min": 0.5, "alpha_max": 0.6}})"), s,
                  "f.json")
                  .empty());
  EXPECT_EQ(s.guiding.alphaMin, 0.5f);
  EXPECT_EQ(s.guiding.alphaMax, 0.6f);
  std::vector<std::string> warnings = applySettingsJson(
      nlohmann::json::parse(R"({"guiding": {"alpha_min": 0.05, "alpha_max": 0.01}})"), s, "f.json");
  ASSERT_EQ(warnings.size(), 1u) << joined(warnings);
  EXPECT_TRUE(mentions(warnings, "\"guiding.alpha_max\"")) << joined(warnings);
  EXPECT_TRUE(mentions(warnings, "alpha-min <= alpha-max")) << joined(warnings);
  EXPECT_NO_THROW(guiding::validate(s.guiding));
  EXPECT_EQ(s.guiding.alphaMax, 0.6f);
  // A value wrong on its own is the one refused, not the bounds that are fine together.
  s.guiding.alphaMin = 0.1f;
  s.guiding.alphaMax = 0.2f;
  warnings = applySettingsJson(
      nlohmann::json::parse(
          R"({"guiding": {"strata": "40x40", "alpha_min": 0.5, "alpha_max": 0.6}})"),
      s, "f.json");
  ASSERT_EQ(warnings.size(), 1u) << joined(warnings);
  EXPECT_TRUE(mentions(warnings, "\"guiding.strata\" \"40x40\": strata must be"))
      << joined(warnings);
  EXPECT_EQ(s.guiding.alphaMin, 0.5f);
  EXPECT_EQ(s.guiding.rows, 8u);
}

TEST(SettingsFile, OptionsGivenOnTheCommandLineWin) {
  Settings s;
  s.render.exposure = 3.0f;  // as parsed from --exposure 3
  auto given = [](const std::string& option) {
    return option == "--exposure" || option == "--strata";
  };
  std::vector<std::string> warnings = applySettingsJson(
      nlohmann::json::parse(
          R"({"render": {"exposure": 0.5, "seed": 9}, "guiding": {"strata": "4x4"}})"),
      s, "f.json", given);
  EXPECT_TRUE(warnings.empty()) << joined(warnings);
  EXPECT_EQ(s.render.exposure, 3.0f);
  EXPECT_EQ(s.guiding.rows, 8u);
  EXPECT_EQ(s.render.seed, 9u);
}

TEST(SettingsFile, MalformedFilesAreOneLineErrorsNamingTheFile) {
  fs::path dir = tempDir();
  write(dir / "bad.json", "{\"render\": {\"seed\": 7,,}}\n");
  write(dir / "array.json", "[1, 2]");
  for (const char* name : {"bad.json", "array.json", "missing.json"}) {
    Settings s;
    try {
      loadSettingsFile(dir / name, s);
      ADD_FAILURE() << name << " loaded";
    } catch (const std::runtime_error& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind((dir / name).string() + ": ", 0), 0u) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }
  Settings s;
  try {
    loadSettingsFile(dir / "bad.json", s);
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("line 1, column"), std::string::npos) << e.what();
  }
}

// The environment's keys: no sky is null; a sky that is not three numbers in range, a file
// that is not a string and a negative strength warn by name and change nothing.
TEST(SettingsFile, EnvironmentKeysAndTheirRefusals) {
  EXPECT_TRUE(settingsToJson(Settings{})["environment"]["sky"].is_null());
  EXPECT_EQ(settingsToJson(Settings{})["environment"]["file"], "");
  Settings s;
  std::vector<std::string> warnings = applySettingsJson(
      nlohmann::json::parse(R"({"environment": {"sky": [1, 2], "file": 7, "strength": -1,
                                                "rotation": 1e9}})"),
      s, "e.json");
  EXPECT_EQ(warnings.size(), 4u) << joined(warnings);
  for (const char* key :
       {"environment.sky", "environment.file", "environment.strength", "environment.rotation"})
    EXPECT_TRUE(mentions(warnings, key)) << key << "\n" << joined(warnings);
  expectSame(s, Settings{});
  warnings = applySettingsJson(nlohmann::json::parse(R"({"environment": {"sky": [0.5, 0, 4]}})"), s,
                               "e.json");
  EXPECT_TRUE(warnings.empty()) << joined(warnings);
  EXPECT_EQ(s.environment.sky, glm::vec3(0.5f, 0.0f, 4.0f));
  applySettingsJson(nlohmann::json::parse(R"({"environment": {"sky": null}})"), s, "e.json");
  EXPECT_FALSE(s.environment.sky.has_value());
}

}  // namespace
}  // namespace qlight::game
