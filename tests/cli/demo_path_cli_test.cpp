// The headless demo along a camera path (--camera-path) and along the scene's own animated
// camera (--camera gltf): every frame written and numbered, the camera where the path says,
// the MP4 when ffmpeg is there, and one error line for a broken path file.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>

#include "tests/cli/run_binary.h"

namespace qlight::test {
namespace {

namespace fs = std::filesystem;

// The Cornell box's camera (0, 1, 3.9) looking down -Z.
constexpr const char* kStill = R"("position": [0, 1, 3.9], "forward": [0, 0, -1], "up": [0, 1, 0])";
// Inside the box, close to its left wall and facing it.
constexpr const char* kMoved =
    R"("position": [0.3, 1, 0.3], "forward": [-1, 0, 0], "up": [0, 1, 0])";

// Still for the first half second, then a move: at 2 fps frames 0 and 1 share a pose and
// frame 2 is elsewhere.
std::string stillThenMovedPath() {
  return std::string("{\"keys\": [{\"time\": 0, ") + kStill + "}, {\"time\": 0.5, " + kStill +
         "}, {\"time\": 1, " + kMoved + "}]}";
}

fs::path writeFile(const fs::path& file, const std::string& text) {
  std::ofstream(file) << text;
  return file;
}

std::string demoAlong(const fs::path& path, const fs::path& out) {
  return "demo --headless --scene " + asset("cornell_box.gltf") + " --camera-path " +
         path.string() + " --fps 2 --width 32 --height 24 --spp-per-frame 4 --out " + out.string();
}

// Mean absolute difference of two PNGs' 8-bit channels.
double meanDifference(const fs::path& a, const fs::path& b) {
  int wa = 0, ha = 0, wb = 0, hb = 0, n = 0;
  unsigned char* pa = stbi_load(a.c_str(), &wa, &ha, &n, 3);
  unsigned char* pb = stbi_load(b.c_str(), &wb, &hb, &n, 3);
  double sum = -1.0;
  if (pa && pb && wa == wb && ha == hb) {
    sum = 0.0;
    for (int i = 0; i < wa * ha * 3; ++i) sum += std::abs(int(pa[i]) - int(pb[i]));
    sum /= double(wa) * ha * 3;
  }
  stbi_image_free(pa);
  stbi_image_free(pb);
  return sum;
}

// Frames 0 and 1 share a pose (they differ by noise), frame 2 looks elsewhere.
void expectOnlyTheLastFrameMoved(const fs::path& dir) {
  const double noise = meanDifference(dir / "frame_0000.png", dir / "frame_0001.png");
  const double moved = meanDifference(dir / "frame_0000.png", dir / "frame_0002.png");
  ASSERT_GE(noise, 0.0) << "frames unreadable or of different sizes";
  EXPECT_GT(moved, 3.0 * noise + 2.0) << "noise " << noise << ", moved " << moved;
}

bool ffmpegInstalled() { return runCommand("command -v ffmpeg").exitCode == 0; }

TEST(DemoPathCli, RendersEveryFrameOfThePathNumbered) {
  const fs::path dir = tempDir("demo_path");
  const fs::path out = dir / "out";
  const fs::path path = writeFile(dir / "path.json", stillThenMovedPath());
  const RunResult r = runQlight(demoAlong(path, out));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  // 1 s at 2 fps, both ends: frames at 0, 0.5 and 1 s, every one written.
  for (const char* name : {"frame_0000.png", "frame_0001.png", "frame_0002.png", "final.png"})
    EXPECT_TRUE(fs::exists(out / name)) << name << "\n" << r.output;
  EXPECT_FALSE(fs::exists(out / "frame_0003.png"));
  const nlohmann::json stats = nlohmann::json::parse(std::ifstream(out / "stats.json"));
  EXPECT_EQ(stats["frames"], 3);
  EXPECT_EQ(stats["camera"], "path");
  ASSERT_EQ(stats["frames_detail"].size(), 3u);
  EXPECT_EQ(stats["frames_detail"][2]["time"], 1.0);
  expectOnlyTheLastFrameMoved(out);
}

// The MP4 goes through ffmpeg: a stand-in on PATH records what qlight asks of it (every
// frame, at the path's fps, H.264 in yuv420p, into out/flythrough.mp4), so this runs
// whether or not ffmpeg is installed; where it is, the real one encodes the same frames.
TEST(DemoPathCli, WritesAnMp4OfTheFramesWithFfmpeg) {
  const fs::path dir = tempDir("demo_mp4");
  const fs::path path = writeFile(dir / "path.json", stillThenMovedPath());
  fs::create_directories(dir / "bin");
  const fs::path standInFfmpeg = writeFile(dir / "bin" / "ffmpeg",
                                           "#!/bin/sh\n"
                                           "echo \"$@\" > \"" +
                                               (dir / "ffmpeg_args.txt").string() +
                                               "\"\n"
                                               "for last; do :; done\n"
                                               "echo mp4 > \"$last\"\n");
  fs::permissions(standInFfmpeg, fs::perms::owner_all);
  const RunResult r = runCommand("PATH=" + (dir / "bin").string() + ":$PATH QLIGHT_VALIDATION=1 " +
                                 std::string(QLIGHT_BINARY) + " " + demoAlong(path, dir / "out"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const fs::path mp4 = dir / "out" / "flythrough.mp4";
  ASSERT_TRUE(fs::exists(mp4)) << r.output;
  std::ifstream argsFile(dir / "ffmpeg_args.txt");
  const std::string args((std::istreambuf_iterator<char>(argsFile)),
                         std::istreambuf_iterator<char>());
  for (const std::string& wanted :
       {std::string("-framerate 2 "), std::string("-frames:v 3 "), std::string("/frame_%04d.png"),
        std::string("-c:v libx264"), std::string("-pix_fmt yuv420p"), mp4.string()})
    EXPECT_NE(args.find(wanted), std::string::npos) << wanted << " not in: " << args;
  EXPECT_FALSE(fs::exists(dir / "out" / "ffmpeg.log")) << "kept only when ffmpeg fails";

  if (ffmpegInstalled()) {  // the real encoder on the same frames
    const RunResult real = runQlight(demoAlong(path, dir / "real"));
    ASSERT_EQ(real.exitCode, 0) << real.output;
    EXPECT_GT(fs::file_size(dir / "real" / "flythrough.mp4"), 100u) << real.output;
    EXPECT_FALSE(fs::exists(dir / "real" / "ffmpeg.log")) << "kept only when ffmpeg fails";
  }
}

TEST(DemoPathCli, WithoutFfmpegOneLineSaysTheMp4WasSkipped) {
  const fs::path dir = tempDir("demo_no_ffmpeg");
  const fs::path path = writeFile(dir / "path.json", stillThenMovedPath());
  const RunResult r = runCommand("PATH=/nonexistent QLIGHT_VALIDATION=1 " +
                                 std::string(QLIGHT_BINARY) + " " + demoAlong(path, dir / "out"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("qlight demo: MP4 skipped: ffmpeg is not on PATH"), std::string::npos)
      << r.output;
  EXPECT_TRUE(fs::exists(dir / "out" / "frame_0002.png"));
  EXPECT_FALSE(fs::exists(dir / "out" / "flythrough.mp4"));
}

// Before any device starts: one "qlight: error: FILE: ..." line and a non-zero exit.
TEST(DemoPathCli, ABrokenPathFileIsOneErrorLine) {
  const fs::path dir = tempDir("demo_bad_path");
  const std::string key0 = std::string("{\"time\": 0, ") + kStill + "}";
  const struct {
    const char* name;
    std::string text;
    const char* says;
  } cases[] = {
      {"truncated", "{\"keys\": [" + key0, "not JSON"},
      {"one_key", "{\"keys\": [" + key0 + "]}", "at least 2 keys"},
      {"nan", "{\"keys\": [" + key0 + R"(, {"time": 1, "position": [NaN, 0, 0]}]})", "not JSON"},
      {"null", "{\"keys\": [" + key0 + R"(, {"time": null, )" + kStill + "}]}",
       "key 1: time is not a number"},
      {"backwards", "{\"keys\": [" + key0 + ", " + key0 + "]}", "is not after"},
  };
  for (const auto& c : cases) {
    const fs::path path = writeFile(dir / (std::string(c.name) + ".json"), c.text);
    const RunResult r = runQlight(demoAlong(path, dir / "out"));
    EXPECT_NE(r.exitCode, 0) << c.name << "\n" << r.output;
    EXPECT_NE(r.output.find("qlight: error: " + path.string() + ": "), std::string::npos)
        << c.name << "\n"
        << r.output;
    EXPECT_NE(r.output.find(c.says), std::string::npos) << c.name << "\n" << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << c.name << "\n" << r.output;
  }
  const RunResult missing = runQlight(demoAlong(dir / "missing.json", dir / "out"));
  EXPECT_NE(missing.exitCode, 0);
  EXPECT_NE(missing.output.find("missing.json: cannot open"), std::string::npos) << missing.output;
}

// The Cornell box with its camera animated: still for a second, then on its way to kMoved's
// position (still facing -Z: the near back wall), reached at 3 s (the demo loops animations,
// so frame 2 at 2 s is half-way there).
fs::path cornellBoxWithAnimatedCamera(const fs::path& dir) {
  nlohmann::json g = nlohmann::json::parse(std::ifstream(asset("cornell_box.gltf")));
  size_t cameraNode = 0;
  while (!g["nodes"][cameraNode].contains("camera")) ++cameraNode;
  const float data[] = {0, 1, 3, 0, 1, 3.9f, 0, 1, 3.9f, 0.3f, 1, 0.3f};
  std::ofstream(dir / "camera_animation.bin", std::ios::binary)
      .write(reinterpret_cast<const char*>(data), sizeof(data));
  const size_t buffer = g["buffers"].size(), view = g["bufferViews"].size(),
               accessor = g["accessors"].size();
  g["buffers"].push_back({{"uri", "camera_animation.bin"}, {"byteLength", sizeof(data)}});
  g["bufferViews"].push_back({{"buffer", buffer}, {"byteOffset", 0}, {"byteLength", 12}});
  g["bufferViews"].push_back({{"buffer", buffer}, {"byteOffset", 12}, {"byteLength", 36}});
  using nlohmann::json;
  g["accessors"].push_back({{"bufferView", view},
                            {"componentType", 5126},
                            {"count", 3},
                            {"type", "SCALAR"},
                            {"min", json::array({0.0})},
                            {"max", json::array({3.0})}});
  g["accessors"].push_back(
      {{"bufferView", view + 1}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}});
  json sampler = {{"input", accessor}, {"output", accessor + 1}};
  json channel = {{"sampler", 0}, {"target", {{"node", cameraNode}, {"path", "translation"}}}};
  g["animations"] =
      json::array({{{"samplers", json::array({sampler})}, {"channels", json::array({channel})}}});
  const fs::path file = dir / "animated_camera.gltf";
  std::ofstream(file) << g.dump();
  return file;
}

TEST(DemoPathCli, GltfCameraPlaysTheScenesOwnAnimatedCamera) {
  const fs::path dir = tempDir("demo_gltf_camera");
  const fs::path scene = cornellBoxWithAnimatedCamera(dir);
  const RunResult r = runQlight("demo --headless --scene " + scene.string() +
                                " --camera gltf --frames 3 --fps 1 --save-every 1 --width 32"
                                " --height 24 --spp-per-frame 4 --out " +
                                (dir / "out").string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const nlohmann::json stats = nlohmann::json::parse(std::ifstream(dir / "out" / "stats.json"));
  EXPECT_EQ(stats["camera"], "gltf");
  expectOnlyTheLastFrameMoved(dir / "out");
}

// Mean absolute difference between horizontally neighbouring pixels of a PNG: its noise.
double roughness(const fs::path& file) {
  int w = 0, h = 0, n = 0;
  unsigned char* p = stbi_load(file.c_str(), &w, &h, &n, 3);
  if (!p) return -1.0;
  double sum = 0.0;
  for (int y = 0; y < h; ++y)
    for (int x = 1; x < w; ++x)
      for (int c = 0; c < 3; ++c)
        sum += std::abs(int(p[(y * w + x) * 3 + c]) - int(p[(y * w + x - 1) * 3 + c]));
  stbi_image_free(p);
  return sum / (double(w - 1) * h * 3);
}

// The headless demo's PNG frames go through the window's display filter unless both parts
// are switched off: the filtered final image is far smoother, and what was traced (rays,
// stats) is the same run.
TEST(DemoCli, HeadlessPngsAreFilteredLikeTheWindowUnlessSwitchedOff) {
  const fs::path dir = tempDir("demo_denoise");
  const std::string base = "demo --headless --scene " + asset("cornell_box.gltf") +
                           " --frames 6 --width 64 --height 48 --out ";
  RunResult raw = runQlight(base + (dir / "raw").string() + " --denoise off --reuse-history off");
  RunResult denoised = runQlight(base + (dir / "denoised").string());
  ASSERT_EQ(raw.exitCode, 0) << raw.output;
  ASSERT_EQ(denoised.exitCode, 0) << denoised.output;
  const double rough = roughness(dir / "raw" / "final.png");
  const double smooth = roughness(dir / "denoised" / "final.png");
  EXPECT_LT(smooth, 0.5 * rough) << "raw " << rough << ", denoised " << smooth;
  auto rays = [](const fs::path& stats) {
    return nlohmann::json::parse(std::ifstream(stats)).at("rays").get<uint64_t>();
  };
  EXPECT_EQ(rays(dir / "raw" / "stats.json"), rays(dir / "denoised" / "stats.json"));
}

// stats.json says which guide rendered, and deep Q's training passes count as its learning
// time (they were left out of it, and the guide was called "q").
TEST(DemoCli, StatsNameTheGuideAndCountDeepQsTraining) {
  const fs::path dir = tempDir("demo_guide_stats");
  auto stats = [&](const std::string& guiding) {
    const fs::path out = dir / guiding;
    RunResult r = runQlight("demo --headless --scene " + asset("cornell_box.gltf") +
                            " --frames 3 --width 32 --height 24 --guiding " + guiding + " --out " +
                            out.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return nlohmann::json::parse(std::ifstream(out / "stats.json"));
  };
  const nlohmann::json dqn = stats("dqn"), q = stats("q"), off = stats("off");
  EXPECT_EQ(dqn.at("guiding"), "dqn");
  EXPECT_EQ(q.at("guiding"), "q");
  EXPECT_EQ(off.at("guiding"), "off");
  const double training = dqn.at("gpu_ms").at("dqn.adam").at("ms_per_frame").get<double>() +
                          dqn.at("gpu_ms").at("dqn.backprop").at("ms_per_frame").get<double>();
  EXPECT_GE(dqn.at("guiding_stats").at("learning_gpu_ms_per_frame").get<double>(), training);
  EXPECT_GT(training, 0.0);
}

}  // namespace
}  // namespace qlight::test
