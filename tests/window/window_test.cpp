// The windowed demo end to end: under a (virtual) X display, `qlight demo`
// opens its window, renders and presents 30 frames with the validation layer
// (synchronization validation on) and exits 0, leaving a non-black screenshot
// at the render resolution (window size times the default render scale). A scripted
// run resizes the window, switches vsync and saves and loads settings files.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>

#include "game/demo_window.h"
#include "tests/support/run_command.h"
#include "tests/window/xvfb_server.h"

namespace qlight::test {
namespace {

namespace fs = std::filesystem;

// Runs `qlight demo` on the Cornell box under a fresh Xvfb display with the validation
// layer on; `dir` receives its outputs.
struct DemoRun {
  RunResult run;
  std::string command;
};

class WindowDemo : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::getenv("DISPLAY") && !XvfbServer::installed())
      GTEST_SKIP() << "no DISPLAY and Xvfb is not installed";
    std::string error;
    // A display of its own per test: ctest runs two at once, and a test that shared the
    // other's server would lose it when the other ends. The numbers come from the test names
    // (143, 146 and 116 today): a new test needs a name whose number is not taken.
    const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    display_ = server_.start(97 + int(std::hash<std::string>{}(name) % 64), error);
    ASSERT_FALSE(display_.empty()) << error;
    dir_ = fs::temp_directory_path() / ("qlight_window_test_" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "xdg");
    fs::permissions(dir_ / "xdg", fs::perms::owner_all, fs::perm_options::replace);
  }
  void TearDown() override { fs::remove_all(dir_); }

  DemoRun runDemo(const std::string& options) {
    DemoRun r;
    r.command = "DISPLAY=" + display_ +
                " QLIGHT_VALIDATION=1 XDG_RUNTIME_DIR=" + (dir_ / "xdg").string() +
                " timeout 600 " + QLIGHT_BINARY + " demo --scene " + QLIGHT_SOURCE_DIR +
                "/assets/cornell_box.gltf --out " + (dir_ / "out").string() + " " + options;
    r.run = runCommand(r.command);
    EXPECT_EQ(r.run.output.find("headless"), std::string::npos)
        << "the demo fell back to headless instead of opening a window:\n"
        << r.run.output;
    return r;
  }

  XvfbServer server_;
  std::string display_;
  fs::path dir_;
};

TEST_F(WindowDemo, PresentsFramesWithoutValidationMessagesAndWritesScreenshot) {
  fs::path shot = dir_ / "shot.png";
  DemoRun demo = runDemo("--exit-after-frames 30 --screenshot-at-exit " + shot.string());
  const RunResult& run = demo.run;
  ASSERT_EQ(run.exitCode, 0) << demo.command << "\n" << run.output;
  EXPECT_NE(run.output.find("30 frames in a"), std::string::npos) << run.output;
  ASSERT_TRUE(fs::exists(shot)) << run.output;

  int w = 0, h = 0, channels = 0;
  unsigned char* pixels = stbi_load(shot.string().c_str(), &w, &h, &channels, 3);
  ASSERT_NE(pixels, nullptr) << stbi_failure_reason();
  game::DemoArgs defaults;
  EXPECT_EQ(w, int(defaults.windowWidth * defaults.window.renderScale));
  EXPECT_EQ(h, int(defaults.windowHeight * defaults.window.renderScale));
  double sum = 0;
  for (int i = 0; i < w * h * 3; ++i) sum += pixels[i];
  stbi_image_free(pixels);
  double mean = sum / (double(w) * h * 3);
  // A black frame (nothing traced, nothing accumulated) has mean 0; the lit
  // Cornell box averages far above 8/255.
  EXPECT_GT(mean, 8.0) << "screenshot is (nearly) black";
}

// --camera-path plays in the window, then the free camera takes over where it ended: a short
// path to the red wall (left) of the Cornell box, facing it. The screenshot is that wall, lit:
// not black, not one flat color, and far redder than green (the box's own camera sees the
// red and the green wall alike).
TEST_F(WindowDemo, PlaysACameraPathThenTheFreeCameraTakesOver) {
  const fs::path path = dir_ / "path.json";
  std::ofstream(path) << R"({"keys": [
    {"time": 0, "position": [0.3, 1, 0.3], "forward": [-1, 0, 0], "up": [0, 1, 0]},
    {"time": 0.05, "position": [0.2, 1, 0.3], "forward": [-1, 0, 0], "up": [0, 1, 0]}]})";
  fs::path shot = dir_ / "shot.png";
  DemoRun demo = runDemo("--camera-path " + path.string() +
                         " --exit-after-frames 8 --screenshot-at-exit " + shot.string());
  const RunResult& run = demo.run;
  ASSERT_EQ(run.exitCode, 0) << demo.command << "\n" << run.output;
  EXPECT_NE(run.output.find("playing camera path " + path.string()), std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("the free camera takes over"), std::string::npos) << run.output;

  int w = 0, h = 0, channels = 0;
  unsigned char* pixels = stbi_load(shot.string().c_str(), &w, &h, &channels, 3);
  ASSERT_NE(pixels, nullptr) << stbi_failure_reason();
  double sum[3] = {0, 0, 0}, squares = 0;
  for (int i = 0; i < w * h; ++i)
    for (int c = 0; c < 3; ++c) {
      sum[c] += pixels[i * 3 + c];
      squares += double(pixels[i * 3 + c]) * pixels[i * 3 + c];
    }
  stbi_image_free(pixels);
  const double n = double(w) * h;
  const double mean = (sum[0] + sum[1] + sum[2]) / (3 * n);
  const double deviation = std::sqrt(std::max(squares / (3 * n) - mean * mean, 0.0));
  EXPECT_GT(mean, 8.0) << "screenshot is (nearly) black";
  EXPECT_GT(deviation, 4.0) << "screenshot is one flat color";
  EXPECT_GT(sum[0], 2.0 * sum[1]) << "not facing the red wall: red " << sum[0] / n << ", green "
                                  << sum[1] / n;
}

// A scripted flight of 12 frames with a target no lavapipe frame meets: the render scale
// goes down while the camera moves and is back at the full scale once it has been still,
// where the image accumulates (the screenshot has the full render size).
TEST_F(WindowDemo, DynamicResolutionLowersWhileMovingAndRestoresWhenStill) {
  fs::path shot = dir_ / "shot.png";
  DemoRun demo = runDemo(
      "--exit-after-frames 24 --scripted-move-frames 12 --target-frame-ms 20"
      " --screenshot-at-exit " +
      shot.string());
  const RunResult& run = demo.run;
  ASSERT_EQ(run.exitCode, 0) << demo.command << "\n" << run.output;
  float now = 0, lowest = 0;
  const size_t at = run.output.find("render scale ");
  ASSERT_NE(at, std::string::npos) << run.output;
  ASSERT_EQ(std::sscanf(run.output.c_str() + at, "render scale %f, lowest %f", &now, &lowest), 2)
      << run.output;
  game::DemoArgs defaults;
  EXPECT_FLOAT_EQ(now, defaults.window.renderScale) << run.output;
  EXPECT_LT(lowest, 0.8f * defaults.window.renderScale) << run.output;
  int w = 0, h = 0, channels = 0;
  ASSERT_TRUE(stbi_info(shot.string().c_str(), &w, &h, &channels)) << run.output;
  EXPECT_EQ(w, int(defaults.windowWidth * defaults.window.renderScale));
}

// A settings file at start, then scripted steps as a user would take them: a resize, vsync
// on, "save settings", "load settings" of another file (its render scale applies) and of a
// missing one (a message, not an exit). Each resize and the vsync switch rebuild the
// swapchain without a validation message; the saved file replays in `qlight render`.
TEST_F(WindowDemo, SettingsFileResizeAndVsyncRebuildSwapchainCleanly) {
  const fs::path start = dir_ / "start.json", later = dir_ / "later.json",
                 saved = dir_ / "saved.json", shot = dir_ / "shot.png";
  std::ofstream(start) << R"({"render": {"exposure": 1.5, "max_depth": 4, "spp_per_frame": 2},
                              "window": {"render_scale": 0.4, "target_frame_ms": 0}})";
  std::ofstream(later) << R"({"render": {"exposure": 2}, "window": {"render_scale": 0.5}})";
  DemoRun demo = runDemo("--settings " + start.string() +
                         " --exit-after-frames 16 --script 3:resize=640x400 --script 6:vsync=on"
                         " --script 9:save=" +
                         saved.string() + " --script 10:load=" + later.string() +
                         " --script 11:load=" + (dir_ / "missing.json").string() +
                         " --screenshot-at-exit " + shot.string());
  const RunResult& run = demo.run;
  ASSERT_EQ(run.exitCode, 0) << demo.command << "\n" << run.output;
  EXPECT_NE(run.output.find("16 frames in a 640x400 window"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("vsync on (FIFO presentation)"), std::string::npos) << run.output;
  unsigned swapchains = 0;
  const size_t at = run.output.find("presentation), ");
  ASSERT_NE(at, std::string::npos) << run.output;
  ASSERT_EQ(std::sscanf(run.output.c_str() + at, "presentation), %u swapchains", &swapchains), 1);
  EXPECT_GE(swapchains, 3u) << run.output;  // the first, the resize, vsync
  EXPECT_NE(run.output.find("loaded settings from " + later.string()), std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("missing.json: cannot open the settings file"), std::string::npos)
      << run.output;

  // What the window had at frame 9: the start file's values, the new size, vsync on.
  std::ifstream in(saved);
  ASSERT_TRUE(in) << run.output;
  nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["render"]["max_depth"], 4);
  EXPECT_EQ(j["render"]["exposure"], 1.5);
  EXPECT_EQ(j["window"]["render_scale"], 0.4);
  EXPECT_EQ(j["window"]["vsync"], true);
  EXPECT_EQ(j["render"]["width"], 256);  // 640 x 0.4: what a still camera accumulates at
  EXPECT_EQ(j["render"]["height"], 160);

  // The later file's scale over the resized window; a lit, varied image.
  int w = 0, h = 0, channels = 0;
  unsigned char* pixels = stbi_load(shot.string().c_str(), &w, &h, &channels, 3);
  ASSERT_NE(pixels, nullptr) << stbi_failure_reason();
  EXPECT_EQ(w, 320);
  EXPECT_EQ(h, 200);
  double sum = 0;
  const auto [lo, hi] = std::minmax_element(pixels, pixels + w * h * 3);
  for (int i = 0; i < w * h * 3; ++i) sum += pixels[i];
  const int spread = int(*hi) - int(*lo);
  stbi_image_free(pixels);
  EXPECT_GT(sum / (double(w) * h * 3), 8.0) << "screenshot is (nearly) black";
  EXPECT_GT(spread, 64) << "screenshot is (nearly) constant";

  // The saved file replays offline at the window's size.
  const fs::path stats = dir_ / "replay.json";
  RunResult replay = runCommand(
      std::string("QLIGHT_VALIDATION=1 ") + QLIGHT_BINARY + " render --scene " + QLIGHT_SOURCE_DIR +
      "/assets/cornell_box.gltf --spp 1 --out " + (dir_ / "replay.png").string() + " --settings " +
      saved.string() + " --stats-json " + stats.string());
  ASSERT_EQ(replay.exitCode, 0) << replay.output;
  EXPECT_EQ(replay.output.find("warning"), std::string::npos) << replay.output;
  nlohmann::json replayed = nlohmann::json::parse(std::ifstream(stats));
  EXPECT_EQ(replayed["width"], 256);
  EXPECT_EQ(replayed["max_depth"], 4);
}

// Seeing the learning: the cache points overlay and the Q view of the point at the image's
// centre (the Cornell box's back wall) draw what the guide learned, validation silent.
TEST_F(WindowDemo, GuideViewsDrawTheCachePointsAndTheQOfThePointAtTheCentre) {
  DemoRun demo = runDemo("--exit-after-frames 12 --show-cache-points --inspect-at 480 270");
  const RunResult& run = demo.run;
  ASSERT_EQ(run.exitCode, 0) << demo.command << "\n" << run.output;
  size_t points = 0;
  float x = 0, y = 0, z = 0;
  const size_t at = run.output.find("guide views: ");
  ASSERT_NE(at, std::string::npos) << run.output;
  ASSERT_EQ(std::sscanf(run.output.c_str() + at,
                        "guide views: %zu cache points drawn, Q shown of the point at %f %f %f",
                        &points, &x, &y, &z),
            4)
      << run.output;
  EXPECT_GT(points, 50u) << run.output;
  // The box spans [-1, 1] in x and z and [0, 2] in y; the centre ray meets its back wall.
  EXPECT_LT(std::abs(x), 1.0f);
  EXPECT_GT(y, 0.2f);
  EXPECT_LT(y, 1.8f);
}

// The display filter in the window: temporal reuse (on by default) and the denoiser while a
// scripted flight moves the camera and after it stops, validation silent.
TEST_F(WindowDemo, DisplayFilterRunsWhileMovingAndStill) {
  DemoRun demo = runDemo("--exit-after-frames 10 --scripted-move-frames 5 --denoise on");
  ASSERT_EQ(demo.run.exitCode, 0) << demo.command << "\n" << demo.run.output;
  EXPECT_NE(demo.run.output.find("10 frames in a"), std::string::npos) << demo.run.output;
}

// Mean absolute difference of two RGB images over the rectangle [x0, x1) x [y0, y1).
double meanDifference(const unsigned char* a, const unsigned char* b, int width, int x0, int y0,
                      int x1, int y1) {
  double sum = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      for (int c = 0; c < 3; ++c)
        sum += std::abs(int(a[(y * width + x) * 3 + c]) - int(b[(y * width + x) * 3 + c]));
  return sum / (3.0 * (x1 - x0) * (y1 - y0));
}

// Everything a session does at once, as issue 12 asks: a settings file loaded, a camera path
// played, the cache points overlay and the denoiser switched on, the window resized, and the
// window captured with its panel (and once without: where the panel is, the two captures
// differ far more than where nothing is drawn over the image); the validation layer silent.
TEST_F(WindowDemo, ScriptedSessionLoadsPlaysTogglesResizesAndCapturesThePanel) {
  const fs::path settings = dir_ / "settings.json", path = dir_ / "path.json";
  std::ofstream(settings) << R"({"render": {"max_depth": 4, "exposure": 1.2}})";
  std::ofstream(path) << R"({"keys": [
    {"time": 0, "position": [0, 1, 3.2], "forward": [0, 0, -1], "up": [0, 1, 0]},
    {"time": 0.1, "position": [0, 1, 3.0], "forward": [0, 0, -1], "up": [0, 1, 0]}]})";
  const fs::path withPanel = dir_ / "with_panel.png", withoutPanel = dir_ / "without_panel.png";
  DemoRun demo = runDemo("--settings " + settings.string() + " --camera-path " + path.string() +
                         " --script 1:points=on --script 2:denoise=on --script 3:resize=800x450"
                         " --script 9:capture=" +
                         withPanel.string() + " --script 10:panel=off --script 10:capture=" +
                         withoutPanel.string() + " --exit-after-frames 11");
  const RunResult& run = demo.run;
  ASSERT_EQ(run.exitCode, 0) << demo.command << "\n" << run.output;
  EXPECT_NE(run.output.find("playing camera path"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("cache points drawn"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("in a 800x450 window"), std::string::npos) << run.output;
  int w = 0, h = 0, w2 = 0, h2 = 0, channels = 0;
  unsigned char* a = stbi_load(withPanel.string().c_str(), &w, &h, &channels, 3);
  unsigned char* b = stbi_load(withoutPanel.string().c_str(), &w2, &h2, &channels, 3);
  ASSERT_NE(a, nullptr) << run.output;
  ASSERT_NE(b, nullptr) << run.output;
  EXPECT_EQ(w, 800);
  EXPECT_EQ(h, 450);
  ASSERT_EQ(w2, w);
  ASSERT_EQ(h2, h);
  double sum = 0, squares = 0;
  for (int i = 0; i < w * h * 3; ++i) sum += a[i], squares += double(a[i]) * a[i];
  const double mean = sum / (3.0 * w * h);
  EXPECT_GT(mean, 8.0) << "the capture is (nearly) black";
  EXPECT_GT(std::sqrt(std::max(squares / (3.0 * w * h) - mean * mean, 0.0)), 4.0)
      << "the capture is one flat colour";
  // The panel stands at the top left (330 pixels wide); the bottom right has nothing over
  // the image but the cache points.
  const double panel = meanDifference(a, b, w, 12, 40, 320, 300);
  const double image = meanDifference(a, b, w, 560, 380, 790, 440);
  EXPECT_GT(panel, 3.0 * image + 5.0) << "panel region " << panel << ", image region " << image;
  stbi_image_free(a);
  stbi_image_free(b);
}

}  // namespace
}  // namespace qlight::test
