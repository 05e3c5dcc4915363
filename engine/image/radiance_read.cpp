#include "engine/image/radiance_read.h"

#include <stb/stb_image.h>
#include <tinyexr.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>

namespace qlight::image {
namespace {

std::runtime_error fileError(const std::filesystem::path& path, const std::string& problem) {
  return std::runtime_error(path.string() + ": " + problem);
}

LinearImage fromRgba(const float* rgba, int width, int height, int channels) {
  LinearImage img;
  img.width = uint32_t(width);
  img.height = uint32_t(height);
  img.rgba.resize(size_t(width) * height * 4);
  for (size_t i = 0; i < size_t(width) * height; ++i) {
    for (int c = 0; c < 3; ++c)
      img.rgba[i * 4 + c] = rgba[i * channels + std::min(c, channels - 1)];
    img.rgba[i * 4 + 3] = 1.0f;
  }
  return img;
}

LinearImage readHdr(const std::filesystem::path& path) {
  std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "rb"), std::fclose);
  if (!file) throw fileError(path, std::string("cannot open: ") + std::strerror(errno));
  // stbi_loadf also decodes PNG or JPEG (as sRGB), which would pass for radiance: refuse them.
  if (!stbi_is_hdr_from_file(file.get())) throw fileError(path, "not a Radiance HDR image");
  int w = 0, h = 0, channels = 0;
  std::unique_ptr<float, void (*)(void*)> pixels(
      stbi_loadf_from_file(file.get(), &w, &h, &channels, 3), stbi_image_free);
  if (!pixels)
    throw fileError(path,
                    std::string("cannot decode the Radiance HDR image: ") + stbi_failure_reason());
  return fromRgba(pixels.get(), w, h, 3);
}

LinearImage readExr(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path))
    throw fileError(path, "cannot open: No such file or directory");
  float* rgba = nullptr;
  int w = 0, h = 0;
  const char* err = nullptr;
  if (LoadEXR(&rgba, &w, &h, path.c_str(), &err) != TINYEXR_SUCCESS) {
    std::string why = err ? err : "unknown error";
    if (err) FreeEXRErrorMessage(err);
    throw fileError(path, "cannot decode the OpenEXR image: " + why);
  }
  std::unique_ptr<float, void (*)(void*)> owned(rgba, std::free);
  return fromRgba(rgba, w, h, 4);
}

}  // namespace

LinearImage readRadianceImage(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  LinearImage img;
  if (ext == ".hdr")
    img = readHdr(path);
  else if (ext == ".exr")
    img = readExr(path);
  else if (ext == ".pfm")
    img = readPfm(path);
  else
    throw fileError(path, "unknown environment map format '" + ext + "' (use .hdr or .exr)");
  if (img.width == 0 || img.height == 0) throw fileError(path, "the image is empty");
  return img;
}

}  // namespace qlight::image
