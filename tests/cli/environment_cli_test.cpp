// `--env`, `--sky`, `--env-strength`, `--env-rotation` as a user runs them: a map (.hdr or
// .exr, written here) lights a scene that has no light, the fallback sky is reported only
// when nothing was chosen, and bad input is one error line with a non-zero exit.
#include <gtest/gtest.h>
#include <stb/stb_image_write.h>
#include <tinyexr.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "engine/image/image_io.h"
#include "tests/cli/run_binary.h"

namespace qlight::test {
namespace {

namespace fs = std::filesystem;

const fs::path kDir = tempDir("environment_cli");

// A sky gradient with a sun: rgb floats, rows from the top.
std::vector<float> skyTexels(int w, int h) {
  std::vector<float> rgb(size_t(w) * h * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      float* p = &rgb[(size_t(y) * w + x) * 3];
      float up = y < h / 2 ? 1.0f - float(y) / float(h) : 0.1f;
      p[0] = 0.4f * up, p[1] = 0.6f * up, p[2] = 1.0f * up;
      if (y == h / 4 && x == w / 2) p[0] = p[1] = p[2] = 500.0f;
    }
  return rgb;
}

fs::path writeHdr(const std::string& name, int w = 32, int h = 16) {
  fs::path file = kDir / name;
  std::vector<float> rgb = skyTexels(w, h);
  EXPECT_NE(stbi_write_hdr(file.c_str(), w, h, 3, rgb.data()), 0);
  return file;
}

fs::path writeExr(const std::string& name, std::vector<float> rgb, int w, int h) {
  fs::path file = kDir / name;
  const char* err = nullptr;
  EXPECT_EQ(SaveEXR(rgb.data(), w, h, 3, /*fp16=*/0, file.c_str(), &err), TINYEXR_SUCCESS);
  if (err) FreeEXRErrorMessage(err);
  return file;
}

void writeText(const fs::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
}

// A tiny render of a scene without lights (BoxTextured: a textured cube, no emitters).
RunResult renderBox(const std::string& options, const std::string& out = "box.pfm") {
  return runQlight("render --scene " + std::string(QLIGHT_SAMPLES_DIR) +
                   "/BoxTextured.gltf --width 24 --height 24 --spp 4 --out " +
                   (kDir / out).string() + " --stats-json " + (kDir / "s.json").string() + " " +
                   options);
}

nlohmann::json stats() {
  std::ifstream in(kDir / "s.json");
  return nlohmann::json::parse(in);
}

double meanRadiance(const fs::path& pfm) {
  image::LinearImage img = image::readPfm(pfm);
  double sum = 0;
  for (size_t i = 0; i < img.rgba.size(); i += 4) sum += img.rgba[i] + img.rgba[i + 1];
  return sum / double(img.width * img.height);
}

size_t countOf(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(EnvironmentCli, HdrAndExrMapsLightASceneWithoutLights) {
  std::vector<float> rgb = skyTexels(32, 16);
  for (const fs::path& map : {writeHdr("sky.hdr"), writeExr("sky.exr", rgb, 32, 16)}) {
    RunResult r = renderBox("--env " + map.string() + " --env-strength 2 --env-rotation 30");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find("fallback"), std::string::npos) << r.output;
    nlohmann::json s = stats();
    EXPECT_EQ(s["fallback_sky"], false);
    EXPECT_EQ(s["environment_light"], true);
    EXPECT_EQ(s["invalid_samples"], 0);
    EXPECT_GT(meanRadiance(kDir / "box.pfm"), 0.05) << map;
  }
}

// Without a choice the fallback sky lights the scene, with a warning saying so; a uniform
// --sky replaces it (and is reported as the environment).
TEST(EnvironmentCli, FallbackSkyOnlyWhenNothingWasChosen) {
  RunResult plain = renderBox("");
  ASSERT_EQ(plain.exitCode, 0) << plain.output;
  EXPECT_NE(plain.output.find("qlight: warning: "), std::string::npos) << plain.output;
  EXPECT_NE(plain.output.find("has no light: lit by a uniform white sky (the fallback"),
            std::string::npos)
      << plain.output;
  EXPECT_EQ(stats()["fallback_sky"], true);
  const double white = meanRadiance(kDir / "box.pfm");

  RunResult sky = renderBox("--sky 0.5,0.5,0.5");
  ASSERT_EQ(sky.exitCode, 0) << sky.output;
  EXPECT_EQ(sky.output.find("fallback"), std::string::npos) << sky.output;
  EXPECT_EQ(stats()["fallback_sky"], false);
  EXPECT_EQ(stats()["environment_light"], true);
  // Radiance is linear in the sky's: half the fallback's, the same paths (same seed).
  EXPECT_NEAR(meanRadiance(kDir / "box.pfm"), 0.5 * white, 1e-3 * white);

  RunResult black = renderBox("--sky 0,0,0");
  ASSERT_EQ(black.exitCode, 0) << black.output;
  EXPECT_NE(black.output.find("qlight: warning: the environment is black"), std::string::npos)
      << black.output;
  EXPECT_EQ(stats()["fallback_sky"], false);
}

// A model whose only emitters are glow maps (MultiUVTest: an emissive texture on TEXCOORD_1) is
// made to be seen under the viewer's light: the fallback sky lights it as well, with a warning
// naming why, and its emissive triangles over black texels are no lights; `--sky 0,0,0` leaves
// it lit by its glow alone.
TEST(EnvironmentCli, GlowMapsAloneGetTheFallbackSkyAsWell) {
  auto render = [&](const std::string& options) {
    return runQlight("render --scene " + std::string(QLIGHT_SAMPLES_DIR) +
                     "/features/MultiUVTest/glTF/MultiUVTest.gltf --width 24 --height 24 --spp 4 "
                     "--out " +
                     (kDir / "glow.pfm").string() + " --stats-json " + (kDir / "s.json").string() +
                     " " + options);
  };
  RunResult plain = render("");
  ASSERT_EQ(plain.exitCode, 0) << plain.output;
  EXPECT_NE(plain.output.find("is lit only by emissive textures (glow maps): lit by a uniform "
                              "white sky as well (the fallback"),
            std::string::npos)
      << plain.output;
  EXPECT_EQ(stats()["fallback_sky"], true);
  EXPECT_EQ(stats()["glow_maps_only"], true);
  const double lit = meanRadiance(kDir / "glow.pfm");

  RunResult dark = render("--sky 0,0,0");
  ASSERT_EQ(dark.exitCode, 0) << dark.output;
  EXPECT_EQ(dark.output.find("fallback"), std::string::npos) << dark.output;
  EXPECT_EQ(stats()["fallback_sky"], false);
  const double glow = meanRadiance(kDir / "glow.pfm");
  EXPECT_GT(glow, 0.0);
  EXPECT_GT(lit, 1.5 * glow);
}

TEST(EnvironmentCli, SettingsFileChoosesTheEnvironment) {
  writeText(kDir / "env.json",
            "{\"environment\": {\"sky\": [0.2, 0.3, 0.4], \"strength\": 2, \"rotation\": 10}}");
  RunResult r = renderBox("--settings " + (kDir / "env.json").string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(r.output.find("warning"), std::string::npos) << r.output;
  EXPECT_EQ(stats()["environment_light"], true);
  // The command line's --env replaces the file's sky.
  RunResult map = renderBox("--settings " + (kDir / "env.json").string() + " --env " +
                            writeHdr("sky2.hdr").string());
  ASSERT_EQ(map.exitCode, 0) << map.output;
  EXPECT_EQ(stats()["environment_map"], (kDir / "sky2.hdr").string());
}

// Each bad input: a non-zero exit and exactly one line "qlight: error: ..." naming the file
// and the problem, before anything renders.
void expectOneErrorLine(const RunResult& r, const std::string& mention, const std::string& why) {
  EXPECT_NE(r.exitCode, 0) << r.output;
  EXPECT_EQ(countOf(r.output, "qlight: error: "), 1u) << r.output;
  EXPECT_EQ(countOf(r.output, "\n"), 1u) << "one line:\n" << r.output;
  EXPECT_NE(r.output.find(mention), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(why), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find(" spp in "), std::string::npos) << "it rendered:\n" << r.output;
}

TEST(EnvironmentCli, MissingOrUnreadableMapsAreOneLineErrors) {
  expectOneErrorLine(renderBox("--env /nonexistent/sky.hdr"), "/nonexistent/sky.hdr",
                     "cannot open");
  expectOneErrorLine(renderBox("--env /nonexistent/sky.exr"), "/nonexistent/sky.exr",
                     "cannot open");
  // (stb_image decodes truncated pixel data as far as it goes: a broken header is what it
  // refuses.)
  writeText(kDir / "corrupt.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y sixteen +X 32\n");
  expectOneErrorLine(renderBox("--env " + (kDir / "corrupt.hdr").string()), "corrupt.hdr",
                     "cannot decode the Radiance HDR image");
  writeText(kDir / "corrupt.exr", std::string("\x76\x2f\x31\x01", 4) + "not an image at all");
  expectOneErrorLine(renderBox("--env " + (kDir / "corrupt.exr").string()), "corrupt.exr",
                     "cannot decode the OpenEXR image");
  // A PNG is not radiance, whatever its name.
  writeText(kDir / "photo.hdr", std::string("\x89PNG\r\n\x1a\n", 8) + "rest");
  expectOneErrorLine(renderBox("--env " + (kDir / "photo.hdr").string()), "photo.hdr",
                     "not a Radiance HDR image");
  writeText(kDir / "sky.png", "whatever");
  expectOneErrorLine(renderBox("--env " + (kDir / "sky.png").string()), "sky.png",
                     "unknown environment map format '.png' (use .hdr or .exr)");
}

TEST(EnvironmentCli, NonFiniteOrNegativeTexelsAreOneLineErrors) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  for (auto [value, word] : {std::pair{nan, "NaN"}, {inf, "infinite"}, {-0.5f, "negative"}}) {
    std::vector<float> rgb = skyTexels(8, 4);
    rgb[(2 * 8 + 5) * 3 + 1] = value;  // texel (5, 2), green
    fs::path map = writeExr(std::string("bad_") + word + ".exr", rgb, 8, 4);
    expectOneErrorLine(renderBox("--env " + map.string()), map.string(),
                       std::string("texel (5, 2) is ") + word);
  }
}

// Options CLI11 refuses: the option named, a non-zero exit, nothing rendered.
TEST(EnvironmentCli, AbsurdStrengthRotationAndSkyAreRejected) {
  const std::string map = " --env " + writeHdr("ok.hdr").string();
  for (const std::string& bad :
       {"--env-strength -1" + map, "--env-strength nan" + map, "--env-strength inf" + map,
        "--env-rotation nan" + map, "--env-rotation 1e9" + map, std::string("--sky 1,2"),
        std::string("--sky a,b,c"), std::string("--sky -1,0,0"), std::string("--sky 1,1,nan"),
        std::string("--sky 1,1,1,1"), "--sky 1,1,1" + map}) {
    RunResult r = renderBox(bad);
    EXPECT_NE(r.exitCode, 0) << bad << "\n" << r.output;
    const std::string option = bad.substr(0, bad.find(' '));
    EXPECT_NE(r.output.find(option), std::string::npos) << bad << "\n" << r.output;
    EXPECT_EQ(r.output.find(" spp in "), std::string::npos) << "it rendered:\n" << r.output;
  }
}

// A map larger than the device's texel buffers (simulated: 30,000 texels per buffer; the map
// has 256 x 128 + its 2 header texels) is refused before anything is allocated, naming the
// map and the limit.
TEST(EnvironmentCli, MapsLargerThanTheDeviceAreRefusedWithTheLimit) {
  const fs::path map = writeHdr("big.hdr", 256, 128);
  RunResult r = runCommand("QLIGHT_TEST_MAX_TEXEL_ELEMENTS=30000 " + std::string(QLIGHT_BINARY) +
                           " render --scene " + std::string(QLIGHT_SAMPLES_DIR) +
                           "/Box.gltf --width 8 --height 8 --spp 1 --out " +
                           (kDir / "big.png").string() + " --env " + map.string());
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("the environment map " + map.string() + " (256x128 texels"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("needs 32770 texels in one buffer; the device allows 30000 "
                          "(maxTexelBufferElements)"),
            std::string::npos)
      << r.output;
}

}  // namespace
}  // namespace qlight::test
