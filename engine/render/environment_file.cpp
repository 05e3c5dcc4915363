#include "engine/render/environment_file.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "engine/image/radiance_read.h"

namespace qlight::render {
namespace {

const char* badValue(float v) {
  if (std::isnan(v)) return "NaN";
  if (std::isinf(v)) return "infinite";
  if (v < 0.0f) return "negative";
  return nullptr;
}

}  // namespace

scene::EnvironmentAsset loadEnvironmentMap(const std::filesystem::path& path) {
  image::LinearImage img = image::readRadianceImage(path);
  scene::EnvironmentAsset env;
  env.name = path.string();
  env.width = img.width;
  env.height = img.height;
  env.radiance.resize(size_t(img.width) * img.height);
  for (size_t i = 0; i < env.radiance.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      const float v = img.rgba[i * 4 + c];
      if (const char* bad = badValue(v))
        throw std::runtime_error(path.string() + ": texel (" + std::to_string(i % img.width) +
                                 ", " + std::to_string(i / img.width) + ") is " + bad +
                                 " (environment radiance must be finite and non-negative)");
      env.radiance[i][c] = v;
    }
  }
  return env;
}

}  // namespace qlight::render
