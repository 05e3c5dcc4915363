#include "engine/image/image_io.h"

#include <stb/stb_image_write.h>
#include <tinyexr.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

#include "shaders/shared/tonemap.h"

namespace qlight::image {
namespace {

std::string lowerExtension(const std::filesystem::path& p) {
  std::string e = p.extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e;
}

void writePfm(const std::filesystem::path& path, const LinearImage& img) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error(path.string() + ": cannot open for writing");
  out << "PF\n" << img.width << " " << img.height << "\n-1.0\n";  // -1: little endian
  std::vector<float> row(size_t(img.width) * 3);
  for (uint32_t y = img.height; y-- > 0;) {  // PFM stores the bottom row first
    for (uint32_t x = 0; x < img.width; ++x)
      for (int c = 0; c < 3; ++c) row[x * 3 + c] = img.rgba[(size_t(y) * img.width + x) * 4 + c];
    out.write(reinterpret_cast<const char*>(row.data()), std::streamsize(row.size() * 4));
  }
  if (!out) throw std::runtime_error(path.string() + ": write failed");
}

void writeExr(const std::filesystem::path& path, const LinearImage& img) {
  const char* err = nullptr;
  int rc = SaveEXR(img.rgba.data(), int(img.width), int(img.height), 4, /*fp16=*/0,
                   path.string().c_str(), &err);
  if (rc != TINYEXR_SUCCESS) {
    std::string why = err ? err : "unknown error";
    if (err) FreeEXRErrorMessage(err);
    throw std::runtime_error(path.string() + ": EXR write failed: " + why);
  }
}

}  // namespace

void checkImageExtension(const std::filesystem::path& path) {
  std::string ext = lowerExtension(path);
  if (ext != ".png" && ext != ".pfm" && ext != ".exr")
    throw std::runtime_error(path.string() + ": unknown image format '" + ext +
                             "' (use .png, .pfm or .exr)");
}

std::vector<uint8_t> toSrgb8(const LinearImage& img, float exposure, Tonemap tonemap) {
  std::vector<uint8_t> out(size_t(img.width) * img.height * 4);
  for (size_t i = 0; i < size_t(img.width) * img.height; ++i) {
    glm::vec3 c = shared::displayFromLinear(
        glm::vec3(img.rgba[i * 4], img.rgba[i * 4 + 1], img.rgba[i * 4 + 2]), exposure,
        uint32_t(tonemap));
    for (int k = 0; k < 3; ++k) out[i * 4 + k] = uint8_t(std::lround(c[k] * 255.0f));
    out[i * 4 + 3] = 255;
  }
  return out;
}

void writeImage(const std::filesystem::path& path, const LinearImage& img, float exposure,
                Tonemap tonemap) {
  if (img.width == 0 || img.height == 0 || img.rgba.size() != size_t(img.width) * img.height * 4)
    throw std::runtime_error(path.string() + ": image has no pixels");
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  std::string ext = lowerExtension(path);
  if (ext == ".png") {
    auto pixels = toSrgb8(img, exposure, tonemap);
    if (!stbi_write_png(path.string().c_str(), int(img.width), int(img.height), 4, pixels.data(),
                        int(img.width * 4)))
      throw std::runtime_error(path.string() + ": PNG write failed");
  } else if (ext == ".pfm") {
    writePfm(path, img);
  } else if (ext == ".exr") {
    writeExr(path, img);
  } else {
    checkImageExtension(path);
  }
}

LinearImage readPfm(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot open");
  std::string magic;
  LinearImage img;
  float scale = 0;
  in >> magic >> img.width >> img.height >> scale;
  in.get();
  if (magic != "PF" || img.width == 0 || img.height == 0 || scale >= 0 || img.width > 65536 ||
      img.height > 65536)
    throw std::runtime_error(path.string() + ": not a little-endian RGB PFM");
  img.rgba.assign(size_t(img.width) * img.height * 4, 1.0f);
  std::vector<float> row(size_t(img.width) * 3);
  for (uint32_t y = img.height; y-- > 0;) {
    in.read(reinterpret_cast<char*>(row.data()), std::streamsize(row.size() * 4));
    if (!in) throw std::runtime_error(path.string() + ": truncated PFM");
    for (uint32_t x = 0; x < img.width; ++x)
      for (int c = 0; c < 3; ++c) img.rgba[(size_t(y) * img.width + x) * 4 + c] = row[x * 3 + c];
  }
  return img;
}

}  // namespace qlight::image
