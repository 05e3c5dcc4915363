// Camera path files: save and load give back the same keys, sampling is exact at the keys,
// in between along the straight line and the shortest rotation, held outside; every broken
// file is one line naming the file and the problem.
#include "game/camera_path.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <stdexcept>

#include "tests/support/temp_dir.h"

namespace qlight::test {
namespace {

namespace fs = std::filesystem;
using game::CameraKey;
using game::CameraPath;

fs::path tempFile(const std::string& name) {
  return test::processTempDir("camera_path_test") / name;
}

void expectNear(const glm::vec3& a, const glm::vec3& b, float tolerance = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

CameraKey key(float time, glm::vec3 position, glm::vec3 forward, float yfov = 0.8f) {
  CameraKey k;
  k.time = time;
  k.view.position = position;
  k.view.forward = glm::normalize(forward);
  k.view.up = {0.0f, 1.0f, 0.0f};
  k.view.yfov = yfov;
  return k;
}

// From looking down -Z to looking down -X (a quarter turn left about +Y), moving along X.
CameraPath quarterTurn() {
  CameraPath p;
  p.keys = {key(1.0f, {0, 1, 2}, {0, 0, -1}, 0.6f), key(3.0f, {4, 1, 2}, {-1, 0, 0}, 1.0f)};
  return p;
}

TEST(CameraPath, SaveThenLoadGivesTheSameKeys) {
  CameraPath p = quarterTurn();
  p.keys.push_back(key(3.5f, {0.1f, 0.3f, -7.25f}, {0.3f, -0.2f, -1.0f}, 0.69f));
  const fs::path file = tempFile("round_trip.json");
  game::saveCameraPath(file, p);
  EXPECT_FALSE(fs::exists(file.string() + ".tmp"));
  const CameraPath back = game::loadCameraPath(file);
  ASSERT_EQ(back.keys.size(), p.keys.size());
  EXPECT_TRUE(back.hasFov);
  for (size_t i = 0; i < p.keys.size(); ++i) {
    // The file holds the shortest decimal of each float, which reads back as the same float.
    EXPECT_EQ(back.keys[i].time, p.keys[i].time);
    EXPECT_EQ(back.keys[i].view.position, p.keys[i].view.position);
    EXPECT_EQ(back.keys[i].view.yfov, p.keys[i].view.yfov);
    expectNear(back.keys[i].view.forward, p.keys[i].view.forward);
    // Up comes back orthogonal to forward, in the plane of forward and the saved up.
    EXPECT_NEAR(glm::dot(back.keys[i].view.up, back.keys[i].view.forward), 0.0f, 1e-6f);
    EXPECT_GT(back.keys[i].view.up.y, 0.9f);
  }
}

TEST(CameraPath, SaveCreatesTheFolderAndReplacesAnOldFile) {
  const fs::path file = tempFile("new/folder/path.json");
  fs::remove_all(file.parent_path());
  game::saveCameraPath(file, quarterTurn());
  CameraPath shorter = quarterTurn();
  shorter.keys.back().time = 2.0f;
  game::saveCameraPath(file, shorter);
  EXPECT_EQ(game::loadCameraPath(file).end(), 2.0f);
}

TEST(CameraPath, SampleIsExactAtTheKeys) {
  const CameraPath p = quarterTurn();
  for (const CameraKey& k : p.keys) EXPECT_EQ(p.sample(k.time), k.view);
}

TEST(CameraPath, SampleInterpolatesBetweenTheKeys) {
  const CameraPath p = quarterTurn();
  const render::CameraView half = p.sample(2.0f);
  expectNear(half.position, {2, 1, 2});
  // Half the quarter turn: 45 degrees between -Z and -X, up still +Y.
  expectNear(half.forward, glm::normalize(glm::vec3(-1, 0, -1)));
  expectNear(half.up, {0, 1, 0});
  EXPECT_NEAR(half.yfov, 0.8f, 1e-6f);
  const render::CameraView quarter = p.sample(1.5f);
  expectNear(quarter.position, {1, 1, 2});
  const float angle = 3.14159265f / 8.0f;  // a constant turning speed (slerp, not a lerp)
  expectNear(quarter.forward, {-std::sin(angle), 0.0f, -std::cos(angle)});
  EXPECT_NEAR(glm::length(quarter.forward), 1.0f, 1e-6f);
}

TEST(CameraPath, SampleHoldsTheEndsOutsideThePath) {
  const CameraPath p = quarterTurn();
  EXPECT_EQ(p.sample(-5.0f), p.keys.front().view);
  EXPECT_EQ(p.sample(0.999f), p.keys.front().view);
  EXPECT_EQ(p.sample(3.001f), p.keys.back().view);
  EXPECT_EQ(p.sample(1e9f), p.keys.back().view);
}

TEST(CameraPath, AFileWithoutFovTakesTheOneGiven) {
  const fs::path file = tempFile("no_fov.json");
  std::ofstream(file) << R"({"keys": [
    {"time": 0, "position": [0, 0, 0], "forward": [0, 0, -1], "up": [0, 1, 0]},
    {"time": 2, "position": [1, 0, 0], "forward": [0, 0, -1], "up": [0, 1, 0]}]})";
  CameraPath p = game::loadCameraPath(file);
  EXPECT_FALSE(p.hasFov);
  p.setFov(0.5f);
  EXPECT_EQ(p.sample(1.0f).yfov, 0.5f);
  EXPECT_TRUE(p.hasFov);
}

// Each broken file: one line (no newline) that names the file and says what is wrong.
TEST(CameraPath, BrokenFilesAreOneLineErrors) {
  const std::string a =
      R"({"time": 0, "position": [0, 0, 0], "forward": [0, 0, -1], "up": [0, 1, 0]})";
  const std::string b =
      R"({"time": 1, "position": [1, 0, 0], "forward": [0, 0, -1], "up": [0, 1, 0]})";
  const struct {
    const char* name;
    std::string text;
    const char* says;
  } cases[] = {
      {"not_json", "{\"keys\": [", "not JSON"},
      {"empty", "", "not JSON"},
      {"no_keys", R"({"frames": []})", "expected {\"keys\""},
      {"one_key", "{\"keys\": [" + a + "]}", "at least 2 keys"},
      {"same_time", "{\"keys\": [" + a + "," + a + "]}",
       "key 1: time 0 is not after the previous key's 0"},
      {"backwards", "{\"keys\": [" + b + "," + a + "]}", "is not after the previous"},
      {"null",
       "{\"keys\": [" + a +
           R"(, {"time": 1, "position": [null, 0, 0], "forward": [0, 0, -1], "up": [0, 1, 0]}]})",
       "key 1: position[0] is not a number"},
      {"infinite",
       "{\"keys\": [" + a +
           R"(, {"time": 1e999, "position": [0, 0, 0], "forward": [0, 0, -1], "up": [0, 1, 0]}]})",
       "number overflow"},
      {"too_big_for_float",
       "{\"keys\": [" + a +
           R"(, {"time": 1, "position": [1e300, 0, 0], "forward": [0, 0, -1], "up": [0, 1, 0]}]})",
       "not a finite number"},
      {"short_vector",
       "{\"keys\": [" + a +
           R"(, {"time": 1, "position": [0, 0], "forward": [0, 0, -1], "up": [0, 1, 0]}]})",
       "key 1: position is not [x, y, z]"},
      {"no_up",
       "{\"keys\": [" + a + R"(, {"time": 1, "position": [0, 0, 0], "forward": [0, 0, -1]}]})",
       "key 1: up is missing"},
      {"parallel",
       "{\"keys\": [" + a +
           R"(, {"time": 1, "position": [0, 0, 0], "forward": [0, 2, 0], "up": [0, 1, 0]}]})",
       "up is zero or parallel"},
      {"zero_forward",
       "{\"keys\": [" + a +
           R"(, {"time": 1, "position": [0, 0, 0], "forward": [0, 0, 0], "up": [0, 1, 0]}]})",
       "forward is zero"},
      {"some_fov",
       "{\"keys\": [" + a +
           R"(, {"time": 1, "position": [0, 0, 0], "forward": [0, 0, -1], "up": [0, 1, 0], "yfov": 0.5}]})",
       "yfov is on 1 of 2 keys"},
      {"bad_fov",
       "{\"keys\": [" + a +
           R"(, {"time": 1, "position": [0, 0, 0], "forward": [0, 0, -1], "up": [0, 1, 0], "yfov": 4}]})",
       "is not in (0, pi)"},
      {"key_not_object", "{\"keys\": [" + a + ", 5]}", "key 1 is not an object"},
  };
  for (const auto& c : cases) {
    const fs::path file = tempFile(std::string(c.name) + ".json");
    std::ofstream(file) << c.text;
    try {
      game::loadCameraPath(file);
      ADD_FAILURE() << c.name << " loaded";
    } catch (const std::runtime_error& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u) << c.name << ": " << message;
      EXPECT_NE(message.find(c.says), std::string::npos) << c.name << ": " << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << c.name << ": " << message;
    }
  }
  try {
    game::loadCameraPath(tempFile("missing.json"));
    ADD_FAILURE() << "a missing file loaded";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("missing.json: cannot open"), std::string::npos)
        << e.what();
  }
}

TEST(CameraPath, SaveIntoAnUnwritablePlaceThrowsNamingTheFile) {
  const fs::path blocker = tempFile("a_file");
  std::ofstream(blocker) << "x";
  const fs::path file = blocker / "path.json";  // a folder that is a file
  try {
    game::saveCameraPath(file, quarterTurn());
    ADD_FAILURE() << "saved";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace qlight::test
