// Writes the environment map qlight ships for demos and the README (assets/sky_sun.hdr): a
// procedural clear sky, 256 x 128 equirectangular (shaders/shared/environment.h's layout),
// bright toward the horizon and deep blue at the zenith, a grey-brown ground, and a sun disc
// of 2 degrees radius 35 degrees above the horizon, 40 degrees right of -Z. Linear radiance;
// the sun gives about as much irradiance as the whole sky. Reloaded after writing as a check.
//
//   gen_environment [--out FILE]      (FILE defaults to ./assets/sky_sun.hdr)
#include <stb/stb_image_write.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "engine/render/environment_file.h"
#include "shaders/shared/environment.h"

namespace {

constexpr int kWidth = 256, kHeight = 128;

glm::vec3 skyRadiance(glm::vec3 d, glm::vec3 sun) {
  const float elevation = std::asin(glm::clamp(d.y, -1.0f, 1.0f));
  if (elevation < 0.0f) {  // ground, a little brighter toward the horizon
    const float h = std::exp(8.0f * elevation);
    return glm::vec3(0.16f, 0.13f, 0.10f) * (0.6f + 0.4f * h);
  }
  const float t = std::pow(1.0f - elevation / (0.5f * qlight::shared::kPi), 3.0f);
  glm::vec3 sky = glm::mix(glm::vec3(0.10f, 0.22f, 0.55f), glm::vec3(0.85f, 0.90f, 1.0f), t);
  const float toSun = std::acos(glm::clamp(glm::dot(d, sun), -1.0f, 1.0f));
  sky += glm::vec3(1.0f, 0.85f, 0.6f) * 0.6f * std::exp(-toSun * 6.0f);  // the glow around it
  if (toSun < glm::radians(2.0f)) sky = glm::vec3(3000.0f, 2800.0f, 2500.0f);
  return sky;
}

}  // namespace

int main(int argc, char** argv) {
  std::string out = "assets/sky_sun.hdr";
  CLI::App app{"writes the shipped environment map"};
  app.add_option("--out", out, "output .hdr file");
  CLI11_PARSE(app, argc, argv);
  const float elevation = glm::radians(35.0f), azimuth = glm::radians(40.0f);
  // phi from -Z toward +X (environment.h).
  const glm::vec3 sun(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                      -std::cos(elevation) * std::cos(azimuth));
  std::vector<float> rgb(size_t(kWidth) * kHeight * 3);
  for (int row = 0; row < kHeight; ++row)
    for (int col = 0; col < kWidth; ++col) {
      const glm::vec2 uv((col + 0.5f) / kWidth, (row + 0.5f) / kHeight);
      const glm::vec3 l = skyRadiance(qlight::shared::environmentDirectionOfUv(uv), sun);
      for (int c = 0; c < 3; ++c) rgb[(size_t(row) * kWidth + col) * 3 + c] = l[c];
    }
  if (!stbi_write_hdr(out.c_str(), kWidth, kHeight, 3, rgb.data())) {
    std::fprintf(stderr, "gen_environment: cannot write %s\n", out.c_str());
    return 1;
  }
  try {
    qlight::render::loadEnvironmentMap(out);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "gen_environment: %s\n", e.what());
    return 1;
  }
  std::printf("gen_environment: %s (%dx%d)\n", out.c_str(), kWidth, kHeight);
  return 0;
}
