// The windowed demo end to end: under a (virtual) X display, `qlight demo`
// opens its window, renders and presents 30 frames with the validation layer
// (synchronization validation on) and exits 0, leaving a non-black screenshot
// at the render resolution (window size times the default render scale).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
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
    // A display of its own per test: ctest runs the two at once, and a test that shared the
    // other's server would lose it when the other ends.
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
  EXPECT_EQ(w, int(defaults.windowWidth * defaults.renderScale));
  EXPECT_EQ(h, int(defaults.windowHeight * defaults.renderScale));
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
  EXPECT_FLOAT_EQ(now, defaults.renderScale) << run.output;
  EXPECT_LT(lowest, 0.8f * defaults.renderScale) << run.output;
  int w = 0, h = 0, channels = 0;
  ASSERT_TRUE(stbi_info(shot.string().c_str(), &w, &h, &channels)) << run.output;
  EXPECT_EQ(w, int(defaults.windowWidth * defaults.renderScale));
}

}  // namespace
}  // namespace qlight::test
