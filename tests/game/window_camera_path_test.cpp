// The window's camera path recording (F9) and playback (--camera-path), fed frames by hand.
#include "game/window_camera_path.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>

#include "tests/support/temp_dir.h"

namespace qlight::test {
namespace {

namespace fs = std::filesystem;

render::CameraView at(float x) {
  render::CameraView v;
  v.position = {x, 1.0f, 0.0f};
  return v;
}

game::DemoArgs recordingInto(const fs::path& file) {
  game::DemoArgs args;
  args.recordPath = file.string();
  return args;
}

fs::path tempFile(const std::string& name) {
  return test::processTempDir("window_path_test") / name;
}

TEST(WindowCameraPath, RecordsAKeyAFrameAndWritesThemOnStop) {
  const fs::path file = tempFile("recorded.json");
  fs::remove(file);
  game::WindowCameraPath paths(recordingInto(file), 0.8f);
  paths.record(at(9.0f), 0.1f);  // not recording yet
  paths.toggleRecording();
  paths.record(at(0.0f), 0.1f);
  paths.record(at(1.0f), 0.25f);
  paths.record(at(1.5f), 0.0f);  // no time passed: replaces the last key
  paths.record(at(2.0f), 0.5f);
  EXPECT_EQ(paths.status(), "recording (3 keys)");
  paths.toggleRecording();
  EXPECT_FALSE(paths.recording());
  EXPECT_NE(paths.status().find("recorded 3 keys"), std::string::npos) << paths.status();
  const game::CameraPath p = game::loadCameraPath(file);
  ASSERT_EQ(p.keys.size(), 3u);
  EXPECT_EQ(p.keys[0].time, 0.0f);
  EXPECT_EQ(p.keys[1].time, 0.25f);
  EXPECT_EQ(p.keys[2].time, 0.75f);
  EXPECT_EQ(p.keys[1].view.position.x, 1.5f);
  EXPECT_EQ(p.keys[2].view.position.x, 2.0f);
}

TEST(WindowCameraPath, ARecordingOfOneKeyWritesNothing) {
  const fs::path file = tempFile("one_key.json");
  fs::remove(file);
  game::WindowCameraPath paths(recordingInto(file), 0.8f);
  paths.toggleRecording();
  paths.record(at(0.0f), 0.1f);
  paths.toggleRecording();
  EXPECT_FALSE(fs::exists(file));
  EXPECT_NE(paths.status().find("nothing written"), std::string::npos) << paths.status();
}

TEST(WindowCameraPath, ClosingTheWindowWritesARecordingInProgress) {
  const fs::path file = tempFile("at_exit.json");
  fs::remove(file);
  game::WindowCameraPath paths(recordingInto(file), 0.8f);
  paths.toggleRecording();
  paths.record(at(0.0f), 0.1f);
  paths.record(at(1.0f), 0.1f);
  paths.finish();
  EXPECT_EQ(game::loadCameraPath(file).keys.size(), 2u);
}

TEST(WindowCameraPath, AFileThatCannotBeWrittenIsAMessageNotAnError) {
  const fs::path blocker = tempFile("blocker");
  std::ofstream(blocker) << "x";
  game::WindowCameraPath paths(recordingInto(blocker / "path.json"), 0.8f);
  paths.toggleRecording();
  paths.record(at(0.0f), 0.1f);
  paths.record(at(1.0f), 0.1f);
  EXPECT_NO_THROW(paths.toggleRecording());
  EXPECT_NE(paths.status().find("not recorded"), std::string::npos) << paths.status();
}

TEST(WindowCameraPath, PlaysThePathFromItsFirstKeyToItsLastThenStops) {
  game::DemoArgs args;
  args.cameraPathFile = "test.json";
  args.cameraPath.keys = {{2.0f, at(0.0f)}, {3.0f, at(4.0f)}};
  args.cameraPath.hasFov = false;
  game::WindowCameraPath paths(args, 0.5f);
  std::vector<float> xs;
  while (std::optional<render::CameraView> v = paths.play(0.375f)) {
    xs.push_back(v->position.x);
    EXPECT_EQ(v->yfov, 0.5f);  // the scene camera's: the file has none
    ASSERT_LT(xs.size(), 10u);
  }
  EXPECT_EQ(xs, (std::vector<float>{0.0f, 1.5f, 3.0f, 4.0f}));
  EXPECT_NE(paths.status().find("played"), std::string::npos) << paths.status();
}

}  // namespace
}  // namespace qlight::test
