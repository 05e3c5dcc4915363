#include "engine/render/texture_mips.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace qlight::render {

float toLinear(uint8_t c, bool srgb) {
  float v = c / 255.0f;
  if (!srgb) return v;
  return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

namespace {

uint8_t fromLinear(float v, bool srgb) {
  v = std::clamp(v, 0.0f, 1.0f);
  if (srgb) v = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
  return uint8_t(std::lround(v * 255.0f));
}

}  // namespace

uint32_t mipLevelCount(uint32_t width, uint32_t height) {
  uint32_t levels = 1;
  for (uint32_t size = std::max(width, height); size > 1; size /= 2) ++levels;
  return levels;
}

uint64_t mipChainTexels(uint32_t width, uint32_t height) {
  uint64_t total = 0;
  for (uint32_t l = 0; l < mipLevelCount(width, height); ++l)
    total += uint64_t(std::max(width >> l, 1u)) * std::max(height >> l, 1u);
  return total;
}

std::vector<uint32_t> buildMipChain(const scene::TextureAsset& t) {
  std::vector<uint32_t> out(mipChainTexels(t.width, t.height));
  std::memcpy(out.data(), t.rgba8.data(), size_t(t.width) * t.height * 4);
  // Linear RGBA of the previous level, for averaging without repeated rounding.
  std::vector<float> prev(size_t(t.width) * t.height * 4);
  for (size_t i = 0; i < prev.size(); ++i)
    prev[i] = toLinear(t.rgba8[i], t.srgb && i % 4 != 3);  // alpha is always linear
  uint32_t w = t.width, h = t.height;
  size_t at = size_t(w) * h;
  for (uint32_t l = 1; l < mipLevelCount(t.width, t.height); ++l) {
    const uint32_t nw = std::max(w / 2, 1u), nh = std::max(h / 2, 1u);
    std::vector<float> next(size_t(nw) * nh * 4);
    for (uint32_t y = 0; y < nh; ++y)
      for (uint32_t x = 0; x < nw; ++x)
        for (int c = 0; c < 4; ++c) {
          float sum = 0.0f;
          for (uint32_t dy = 0; dy < 2; ++dy)
            for (uint32_t dx = 0; dx < 2; ++dx) {
              const uint32_t sx = std::min(2 * x + dx, w - 1), sy = std::min(2 * y + dy, h - 1);
              sum += prev[(size_t(sy) * w + sx) * 4 + size_t(c)];
            }
          next[(size_t(y) * nw + x) * 4 + size_t(c)] = 0.25f * sum;
        }
    for (size_t p = 0; p < size_t(nw) * nh; ++p) {
      uint8_t rgba[4];
      for (int c = 0; c < 4; ++c) rgba[c] = fromLinear(next[p * 4 + size_t(c)], t.srgb && c != 3);
      std::memcpy(&out[at + p], rgba, 4);
    }
    at += size_t(nw) * nh;
    prev = std::move(next);
    w = nw;
    h = nh;
  }
  return out;
}

}  // namespace qlight::render
