#include "engine/render/emitter_power.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "engine/render/scene_packing.h"
#include "engine/render/texture_mips.h"

namespace qlight::render {
namespace {

constexpr float kMaxBoxTexels = 8.0f;  // the UV box's extent at the level averaged over
constexpr int kMaxBoxArea = 64 * 64;   // larger (UVs over many repeats): the whole texture

struct MeanLevel {
  int width = 1, height = 1;
  std::vector<glm::vec3> rgb;
  glm::vec3 at(int x, int y) const { return rgb[size_t(y) * size_t(width) + size_t(x)]; }
};

// The texture's linear RGB at each mip level: each level the 2x2 mean of the previous, edge
// texels repeated for odd sizes (texture_mips.cpp's filter, kept in float so that no mean of
// faint texels rounds to 0).
struct MeanPyramid {
  std::vector<MeanLevel> levels;
  scene::TextureWrap wrapS = scene::TextureWrap::Repeat, wrapT = scene::TextureWrap::Repeat;
};

MeanPyramid buildPyramid(const scene::TextureAsset& t) {
  MeanPyramid p;
  p.wrapS = t.wrapS;
  p.wrapT = t.wrapT;
  float linear[256];
  for (int i = 0; i < 256; ++i) linear[i] = toLinear(uint8_t(i), t.srgb);
  MeanLevel base;
  base.width = int(std::max(t.width, 1u));
  base.height = int(std::max(t.height, 1u));
  base.rgb.resize(size_t(base.width) * size_t(base.height), glm::vec3(1.0f));
  for (size_t i = 0; i < base.rgb.size() && i * 4 + 2 < t.rgba8.size(); ++i)
    base.rgb[i] = {linear[t.rgba8[i * 4]], linear[t.rgba8[i * 4 + 1]], linear[t.rgba8[i * 4 + 2]]};
  p.levels.push_back(std::move(base));
  while (p.levels.back().width > 1 || p.levels.back().height > 1) {
    const MeanLevel& prev = p.levels.back();
    MeanLevel next;
    next.width = std::max(prev.width / 2, 1);
    next.height = std::max(prev.height / 2, 1);
    next.rgb.resize(size_t(next.width) * size_t(next.height));
    for (int y = 0; y < next.height; ++y)
      for (int x = 0; x < next.width; ++x) {
        glm::vec3 sum(0.0f);
        for (int dy = 0; dy < 2; ++dy)
          for (int dx = 0; dx < 2; ++dx)
            sum += prev.at(std::min(2 * x + dx, prev.width - 1),
                           std::min(2 * y + dy, prev.height - 1));
        next.rgb[size_t(y) * size_t(next.width) + size_t(x)] = 0.25f * sum;
      }
    p.levels.push_back(std::move(next));
  }
  return p;
}

int wrapIndex(int i, int n, scene::TextureWrap wrap) {
  if (wrap == scene::TextureWrap::ClampToEdge) return std::clamp(i, 0, n - 1);
  if (wrap == scene::TextureWrap::MirroredRepeat) {
    const int m = ((i % (2 * n)) + 2 * n) % (2 * n);
    return m < n ? m : 2 * n - 1 - m;
  }
  return ((i % n) + n) % n;
}

float luminance(glm::vec3 c) { return glm::dot(c, glm::vec3(0.2126f, 0.7152f, 0.0722f)); }

float edge(glm::vec2 a, glm::vec2 b, glm::vec2 p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

glm::vec3 meanOverTriangle(const MeanPyramid& p, const glm::vec2 uv[3]) {
  const glm::vec3 whole = p.levels.back().rgb[0];
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(uv[k].x) || !std::isfinite(uv[k].y)) return whole;
  // The coarsest level still finer than the box's kMaxBoxTexels.
  size_t level = 0;
  glm::vec2 q[3];
  for (;; ++level) {
    const MeanLevel& l = p.levels[level];
    for (int k = 0; k < 3; ++k) q[k] = uv[k] * glm::vec2(float(l.width), float(l.height));
    const glm::vec2 extent =
        glm::max(glm::max(q[0], q[1]), q[2]) - glm::min(glm::min(q[0], q[1]), q[2]);
    if (std::max(extent.x, extent.y) <= kMaxBoxTexels || level + 1 == p.levels.size()) break;
  }
  const MeanLevel& l = p.levels[level];
  const glm::vec2 lo = glm::min(glm::min(q[0], q[1]), q[2]),
                  hi = glm::max(glm::max(q[0], q[1]), q[2]);
  // The texels under the box, floor(lo) .. ceil(hi) - 1, and one more on each side.
  const int x0 = int(std::floor(lo.x)) - 1, y0 = int(std::floor(lo.y)) - 1;
  const int x1 = std::max(int(std::ceil(hi.x)), x0 + 2),
            y1 = std::max(int(std::ceil(hi.y)), y0 + 2);
  if ((x1 - x0 + 1) * (y1 - y0 + 1) > kMaxBoxArea) return whole;
  const float orientation = edge(q[0], q[1], q[2]) < 0.0f ? -1.0f : 1.0f;
  glm::vec3 boxSum(0.0f), insideSum(0.0f);
  int boxCount = 0, insideCount = 0;
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const glm::vec3 v = l.at(wrapIndex(x, l.width, p.wrapS), wrapIndex(y, l.height, p.wrapT));
      boxSum += v;
      ++boxCount;
      const glm::vec2 c(float(x) + 0.5f, float(y) + 0.5f);
      if (orientation * edge(q[0], q[1], c) >= 0.0f && orientation * edge(q[1], q[2], c) >= 0.0f &&
          orientation * edge(q[2], q[0], c) >= 0.0f) {
        insideSum += v;
        ++insideCount;
      }
    }
  if (insideCount > 0 && luminance(insideSum) > 0.0f) return insideSum / float(insideCount);
  return boxSum / float(boxCount);
}

}  // namespace

std::vector<std::vector<glm::vec3>> triangleEmissions(const scene::SceneAsset& scene) {
  std::map<int32_t, MeanPyramid> pyramids;  // built once per emissive texture
  std::vector<std::vector<glm::vec3>> out(scene.meshes.size());
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const scene::MeshAsset& mesh = scene.meshes[m];
    bool emits = false;
    for (uint32_t material : mesh.triangleMaterials)
      emits |= scene.materials[material].isEmissive();
    if (!emits) continue;
    out[m].resize(mesh.triangleCount(), glm::vec3(0.0f));
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
      const scene::MaterialAsset& material = scene.materials[mesh.triangleMaterials[t]];
      if (!material.isEmissive()) continue;
      const scene::TextureBinding& b = material.emissiveTexture;
      if (!b.present() || size_t(b.index) >= scene.textures.size()) {
        out[m][t] = material.emissive;
        continue;
      }
      auto it = pyramids.find(b.index);
      if (it == pyramids.end())
        it = pyramids.emplace(b.index, buildPyramid(scene.textures[size_t(b.index)])).first;
      const TextureTransformRows transform = textureTransformRows(b);
      const std::vector<glm::vec2>& uvs =
          b.texCoord == 1 && !mesh.uv1.empty() ? mesh.uv1 : mesh.uv0;
      glm::vec2 uv[3];
      for (int k = 0; k < 3; ++k) uv[k] = transform.apply(uvs[mesh.indices[t * 3 + size_t(k)]]);
      out[m][t] = material.emissive * meanOverTriangle(it->second, uv);
    }
  }
  return out;
}

}  // namespace qlight::render
