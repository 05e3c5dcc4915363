// The `qlight render` command as a user runs it: outputs, stats, determinism,
// and clear errors on bad input.
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "engine/image/image_io.h"
#include "tests/cli/run_binary.h"

namespace qlight::test {
namespace {

// Outputs go to a folder the test process removes when it exits.
const std::string kTmp = tempDir("render_cli").string();

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(RenderCli, WritesImageAndStatsWithEveryField) {
  fs::path dir = tempDir("stats");
  auto r = runQlight("render --scene " + asset("cornell_box.gltf") +
                     " --width 48 --height 32 --spp 4 --out " + (dir / "cb.png").string() +
                     " --stats-json " + (dir / "s.json").string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  ASSERT_TRUE(fs::exists(dir / "cb.png"));
  auto j = nlohmann::json::parse(slurp(dir / "s.json"));
  for (const char* key : {"width", "height", "spp", "seconds", "rays", "rays_per_second", "paths",
                          "emitter_hit_share", "mean_path_length", "gpu_ms"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["width"], 48);
  EXPECT_EQ(j["spp"], 4);
  EXPECT_EQ(j["paths"], 48u * 32u * 4u);
  EXPECT_GE(j["rays"].get<double>(), j["paths"].get<double>());  // at least the camera rays
  EXPECT_GT(j["rays_per_second"].get<double>(), 0.0);
  EXPECT_GE(j["emitter_hit_share"].get<double>(), 0.0);
  EXPECT_LE(j["emitter_hit_share"].get<double>(), 1.0);
  EXPECT_GT(j["mean_path_length"].get<double>(), 0.5);  // the box is closed: every path bounces
  // lavapipe is a CPU device: its default traces the extension rays in the shade pass.
  EXPECT_EQ(j["trace_kernel"], "fused");
  EXPECT_FALSE(j["gpu_ms"].contains("path.trace"));
  EXPECT_TRUE(j["gpu_ms"].contains("path.shade"));
  EXPECT_EQ(j["invalid_samples"], 0);
}

TEST(RenderCli, TraceKernelIsChosenByTheUser) {
  fs::path dir = tempDir("kernel");
  auto r = runQlight("render --scene " + asset("cornell_box.gltf") +
                     " --width 16 --height 16 --spp 2 --trace-kernel separate --out " +
                     (dir / "cb.png").string() + " --stats-json " + (dir / "s.json").string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  auto j = nlohmann::json::parse(slurp(dir / "s.json"));
  EXPECT_EQ(j["trace_kernel"], "separate");
  EXPECT_TRUE(j["gpu_ms"].contains("path.trace"));
  auto bad = runQlight("render --scene " + asset("cornell_box.gltf") +
                       " --trace-kernel sideways --out " + (dir / "x.png").string());
  EXPECT_NE(bad.exitCode, 0);
  EXPECT_NE(bad.output.find("--trace-kernel"), std::string::npos) << bad.output;
}

TEST(RenderCli, SameSeedSameImageOtherSeedOtherImage) {
  fs::path dir = tempDir("seed");
  std::string base =
      "render --scene " + asset("cornell_box.gltf") + " --width 24 --height 24 --spp 2 ";
  ASSERT_EQ(runQlight(base + "--seed 5 --out " + (dir / "a.pfm").string()).exitCode, 0);
  ASSERT_EQ(runQlight(base + "--seed 5 --out " + (dir / "b.pfm").string()).exitCode, 0);
  ASSERT_EQ(runQlight(base + "--seed 6 --out " + (dir / "c.pfm").string()).exitCode, 0);
  EXPECT_EQ(slurp(dir / "a.pfm"), slurp(dir / "b.pfm"));
  EXPECT_NE(slurp(dir / "a.pfm"), slurp(dir / "c.pfm"));
}

TEST(RenderCli, WritesExr) {
  fs::path dir = tempDir("exr");
  auto r = runQlight("render --scene " + asset("cornell_box.gltf") +
                     " --width 16 --height 16 --spp 1 --out " + (dir / "x.exr").string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::string bytes = slurp(dir / "x.exr");
  ASSERT_GE(bytes.size(), 4u);
  EXPECT_EQ(uint8_t(bytes[0]), 0x76);  // OpenEXR magic 76 2f 31 01
  EXPECT_EQ(uint8_t(bytes[1]), 0x2f);
}

// Depth 0 shows emitters only: a pixel is either black or the emitter's radiance.
TEST(RenderCli, MaxDepthZeroShowsOnlyEmitters) {
  fs::path dir = tempDir("depth0");
  auto r =
      runQlight("render --scene " + asset("cornell_box.gltf") +
                " --width 64 --height 64 --spp 4 --max-depth 0 --out " + (dir / "d.pfm").string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  image::LinearImage img = image::readPfm(dir / "d.pfm");
  // cornell_box.gltf: emissive (1, 0.70588, 0.23529) x strength 17.
  const float emission[3] = {17.0f, 17.0f * 0.70588235f, 17.0f * 0.23529412f};
  size_t lit = 0;
  for (size_t i = 0; i < size_t(img.width) * img.height; ++i) {
    float r0 = img.rgba[i * 4];
    if (r0 == 0.0f) continue;
    ++lit;
    // Partly covered edge pixels average emitter and black: the ratio of channels stays.
    EXPECT_LE(r0, emission[0] * 1.0001f);
    EXPECT_NEAR(img.rgba[i * 4 + 1] / r0, emission[1] / emission[0], 1e-4);
  }
  EXPECT_GT(lit, 0u);
  EXPECT_LT(lit, size_t(img.width) * img.height / 4);
}

TEST(RenderCli, MissingSceneIsAOneLineErrorNamingTheFile) {
  auto r = runQlight("render --scene /nonexistent/scene.gltf --out " + kTmp + "/x.png");
  EXPECT_NE(r.exitCode, 0);
  EXPECT_NE(r.output.find("qlight: error:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("/nonexistent/scene.gltf"), std::string::npos) << r.output;
}

TEST(RenderCli, MalformedSceneIsAnError) {
  fs::path dir = tempDir("malformed");
  std::ofstream(dir / "bad.gltf") << "{ \"asset\": { \"version\": \"2.0\" }, \"nodes\": [ oops";
  auto r = runQlight("render --scene " + (dir / "bad.gltf").string() + " --out " +
                     (dir / "x.png").string());
  EXPECT_NE(r.exitCode, 0);
  EXPECT_NE(r.output.find("bad.gltf"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir / "x.png"));
}

TEST(RenderCli, UnknownImageFormatIsAnError) {
  auto r = runQlight("render --scene " + asset("cornell_box.gltf") +
                     " --width 8 --height 8 --spp 1 --out " + kTmp + "/qlight_x.bmp");
  EXPECT_NE(r.exitCode, 0);
  EXPECT_NE(r.output.find("qlight_x.bmp"), std::string::npos) << r.output;
}

TEST(RenderCli, AbsurdSettingsAreRejected) {
  std::string base =
      "render --scene " + asset("cornell_box.gltf") + " --out " + kTmp + "/qlight_y.png ";
  for (const char* bad :
       {"--width 0", "--height -3", "--spp 0", "--max-depth 100000", "--exposure nan",
        "--exposure -1", "--estimator magic", "--rr maybe", "--time -1", "--strata 0x8",
        "--strata 8by8", "--strata 64x64", "--alpha-min 0.5 --alpha-max 0.1", "--points 2000000",
        "--select-probability 1", "--time nan", "--time inf", "--exposure inf",
        "--temporal-blend nan"}) {
    auto r = runQlight(base + bad);
    EXPECT_NE(r.exitCode, 0) << bad << "\n" << r.output;
  }
}

// Requests larger than the device are refused before anything is allocated, naming what is
// too big and the limit: a render whose path state exceeds the texel-buffer limit (any
// conformant device allows at least 65536 texels; 16384 x 16384 pixels need 3.7e9), and a
// Q table of a million points x 1024 strata (8 GB of sums against at least 128 MiB).
TEST(RenderCli, RequestsLargerThanTheDeviceAreRefusedWithTheLimit) {
  const std::string base =
      "render --scene " + asset("cornell_box.gltf") + " --out " + kTmp + "/qlight_big.png --spp 1 ";
  for (const char* big :
       {"--width 16384 --height 16384", "--width 16 --height 16 --points 1000000 --strata 32x32"}) {
    auto r = runQlight(base + big);
    EXPECT_NE(r.exitCode, 0) << big << "\n" << r.output;
    EXPECT_NE(r.output.find("is larger than"), std::string::npos) << big << "\n" << r.output;
    EXPECT_NE(r.output.find("the device allows"), std::string::npos) << big << "\n" << r.output;
    EXPECT_EQ(r.output.find("VK_ERROR"), std::string::npos) << big << "\n" << r.output;
  }
}

// A texture larger than the device allows (simulated: a device of 20,000 texels per buffer;
// BoxTextured's image has 211 x 211) is refused before anything is allocated, naming the
// textures and the limit.
TEST(RenderCli, TexturesLargerThanTheDeviceAreRefusedWithTheLimit) {
  RunResult r = runCommand("QLIGHT_TEST_MAX_TEXEL_ELEMENTS=20000 " + std::string(QLIGHT_BINARY) +
                           " render --scene " + std::string(QLIGHT_SAMPLES_DIR) +
                           "/BoxTextured.gltf --out " + kTmp +
                           "/qlight_bigtex.png --spp 1 --width 8 "
                           "--height 8");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("the scene's textures (1 images, 59141 texels with their mipmaps"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("the device allows 20000 (maxTexelBufferElements)"), std::string::npos)
      << r.output;
}

// Geometry larger than the device allows (simulated: 40 texels per buffer; Box's 24 vertices
// need 48, its 12 triangles 36 in the BVH) is refused before the BVH is built, in one line
// naming the geometry and the limit.
TEST(RenderCli, GeometryLargerThanTheDeviceIsRefusedWithTheLimit) {
  RunResult r =
      runCommand("QLIGHT_TEST_MAX_TEXEL_ELEMENTS=40 " + std::string(QLIGHT_BINARY) +
                 " render --scene " + std::string(QLIGHT_SAMPLES_DIR) + "/Box.gltf --out " + kTmp +
                 "/qlight_biggeo.png --spp 1 --width 4 --height 4");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("the scene's geometry (12 triangles, 24 vertices in 1 meshes"),
            std::string::npos)
      << r.output;
  EXPECT_NE(
      r.output.find("needs 48 texels in one buffer; the device allows 40 (maxTexelBufferElements)"),
      std::string::npos)
      << r.output;
  size_t lines = 0;
  for (char c : r.output) lines += c == '\n';
  EXPECT_LE(lines, 2u) << r.output;  // the device line and the error
}

// No Vulkan driver at all (the loader finds no ICD): one line that says what to install,
// and a non-zero exit, for render, demo and bench alike.
TEST(RenderCli, NoVulkanDeviceIsAOneLineError) {
  for (const std::string& args :
       {"render --scene " + asset("cornell_box.gltf") + " --out " + kTmp +
            "/qlight_nodev.png --spp 1",
        std::string("demo --headless --frames 1 --out " + kTmp + "/qlight_nodev"),
        "bench --quick --scene " + asset("cornell_box.gltf") + " --out " + kTmp +
            "/qlight_nodev_bench"}) {
    RunResult r = runCommand(
        "VK_ICD_FILENAMES=/nonexistent/icd.json VK_DRIVER_FILES="
        "/nonexistent/icd.json " +
        std::string(QLIGHT_BINARY) + " " + args);
    EXPECT_NE(r.exitCode, 0) << args << "\n" << r.output;
    EXPECT_NE(r.output.find("no Vulkan"), std::string::npos) << args << "\n" << r.output;
    EXPECT_EQ(r.output.find("VK_ERROR"), std::string::npos) << args << "\n" << r.output;
  }
}

// A device lost mid-run (simulated: the 30th submission reports VK_ERROR_DEVICE_LOST) ends
// render, demo and bench with one line saying so and exit code 1, not a crash or a hang.
TEST(RenderCli, ADeviceLostMidRunIsAOneLineError) {
  for (const std::string& args :
       {"render --scene " + asset("door_ajar.gltf") + " --out " + kTmp +
            "/qlight_lost.png --spp 64 --batch 1 --width 32 --height 18",
        std::string("demo --headless --frames 60 --width 32 --height 18 --out " + kTmp +
                    "/qlight_lost"),
        "bench --quick --scene " + asset("cornell_box.gltf") + " --out " + kTmp +
            "/qlight_lost_bench " + "--cache " + kTmp + "/qlight_lost_bench/cache --no-report"}) {
    RunResult r =
        runCommand("QLIGHT_TEST_LOSE_DEVICE_AFTER=30 " + std::string(QLIGHT_BINARY) + " " + args);
    EXPECT_EQ(r.exitCode, 1) << args << "\n" << r.output;
    EXPECT_NE(r.output.find("qlight: error: the Vulkan device was lost"), std::string::npos)
        << args << "\n"
        << r.output;
    const size_t first = r.output.find("qlight: error:");
    EXPECT_EQ(r.output.find("qlight: error:", first + 1), std::string::npos) << "one line";
    EXPECT_EQ(r.output.find("terminate"), std::string::npos) << args << "\n" << r.output;
  }
}

// Non-finite numbers are refused like any other out-of-range value: one line naming the
// option, before anything is loaded or rendered.
TEST(DemoCli, NonFiniteNumbersAreRejected) {
  for (const char* bad : {"--fps nan", "--move-seconds nan", "--move-seconds inf",
                          "--target-frame-ms nan", "--render-scale nan", "--exposure nan"}) {
    auto r =
        runQlight(std::string("demo --headless --frames 1 --out " + kTmp + "/qlight_nan ") + bad);
    EXPECT_NE(r.exitCode, 0) << bad << "\n" << r.output;
    const std::string option = std::string(bad).substr(0, std::string(bad).find(' '));
    EXPECT_NE(r.output.find(option), std::string::npos) << bad << "\n" << r.output;
    EXPECT_EQ(r.output.find("frames of"), std::string::npos) << "it rendered:\n" << r.output;
  }
}

TEST(DemoCli, HeadlessDemoWritesFramesAndStats) {
  fs::path dir = tempDir("demo");
  auto r = runQlight("demo --headless --frames 3 --width 32 --height 24 --out " + dir.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir / "final.png"));
  auto j = nlohmann::json::parse(slurp(dir / "stats.json"));
  EXPECT_EQ(j["frames"], 3);
  EXPECT_EQ(j["frames_detail"].size(), 3u);
}

}  // namespace
}  // namespace qlight::test
