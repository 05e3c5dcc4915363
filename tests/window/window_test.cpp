// The windowed demo end to end: under a (virtual) X display, `qlight demo`
// opens its window, renders and presents 30 frames with the validation layer
// (synchronization validation on) and exits 0, leaving a non-black screenshot
// at the render resolution (window size times the default render scale).
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
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

TEST(WindowDemo, PresentsFramesWithoutValidationMessagesAndWritesScreenshot) {
  if (!std::getenv("DISPLAY") && !XvfbServer::installed())
    GTEST_SKIP() << "no DISPLAY and Xvfb is not installed";
  XvfbServer server;
  std::string error;
  std::string display = server.start(97, error);
  ASSERT_FALSE(display.empty()) << error;

  fs::path dir = fs::temp_directory_path() / ("qlight_window_test_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "xdg");
  fs::permissions(dir / "xdg", fs::perms::owner_all, fs::perm_options::replace);
  fs::path shot = dir / "shot.png";
  std::string command =
      "DISPLAY=" + display + " QLIGHT_VALIDATION=1 XDG_RUNTIME_DIR=" + (dir / "xdg").string() +
      " timeout 600 " + QLIGHT_BINARY + " demo --scene " + QLIGHT_SOURCE_DIR +
      "/assets/cornell_box.gltf" + " --exit-after-frames 30 --screenshot-at-exit " + shot.string() +
      " --out " + (dir / "out").string();
  RunResult run = runCommand(command);
  ASSERT_EQ(run.exitCode, 0) << command << "\n" << run.output;
  EXPECT_EQ(run.output.find("headless"), std::string::npos)
      << "the demo fell back to headless instead of opening a window:\n"
      << run.output;
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
  fs::remove_all(dir);
}

}  // namespace
}  // namespace qlight::test
