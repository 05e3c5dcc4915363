#include "game/bench/bench_reference.h"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <span>
#include <string_view>

#include "engine/session/offline_render.h"
#include "game/bench/bench_metrics.h"

namespace qlight::shaders {
std::span<const uint32_t> findSpirv(std::string_view name);  // embedded_shaders.cpp
}

namespace qlight::game::bench {
namespace {

// Bumped when host code changes what an unguided render computes (scene upload, BVH,
// camera, accumulation); the shaders' part of the version is their SPIR-V.
constexpr uint32_t kHostRenderVersion = 1;

struct Fnv1a {
  uint64_t h = 1469598103934665603ull;
  void add(const void* data, size_t n) {
    auto* p = static_cast<const uint8_t*>(data);
    for (size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 1099511628211ull;
  }
  template <class T>
  void add(const T& v) {
    add(&v, sizeof(v));
  }
  std::string hex() const {
    char s[17];
    std::snprintf(s, sizeof(s), "%016llx", static_cast<unsigned long long>(h));
    return s;
  }
};

std::string cacheKey(const std::filesystem::path& sceneFile, const render::RenderSettings& s,
                     uint32_t spp, float time) {
  Fnv1a f;
  std::ifstream in(sceneFile, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  f.add(bytes.data(), bytes.size());
  f.add(s.width);
  f.add(s.height);
  f.add(s.maxDepth);
  f.add(s.seed);
  f.add(s.estimator);
  f.add(s.russianRoulette);
  f.add(spp);
  if (time != 0.0f) f.add(time);  // keys of time-0 references stay as they were
  std::string version = rendererVersion();
  f.add(version.data(), version.size());
  return f.hex();
}

image::LinearImage average(const image::LinearImage& a, const image::LinearImage& b) {
  image::LinearImage out = a;
  for (size_t i = 0; i < out.rgba.size(); ++i) out.rgba[i] = 0.5f * (a.rgba[i] + b.rgba[i]);
  return out;
}

}  // namespace

std::string rendererVersion() {
  Fnv1a f;
  for (const char* name : {"pt_begin", "pt_trace", "pt_shade", "pt_end", "pt_queue"}) {
    std::span<const uint32_t> words = shaders::findSpirv(name);
    f.add(words.data(), words.size_bytes());
  }
  f.add(kHostRenderVersion);
  return f.hex().substr(0, 12);
}

Reference loadOrRenderReference(const gpu::Context& ctx, const scene::SceneAsset& asset,
                                const std::filesystem::path& sceneFile,
                                const render::RenderSettings& settings, uint32_t spp,
                                const std::filesystem::path& cacheDir, ProgressBar& progress,
                                double progressBase, const std::string& sceneName, float time) {
  const std::string key = cacheKey(sceneFile, settings, spp, time);
  const auto imagePath = cacheDir / (key + ".pfm"), infoPath = cacheDir / (key + ".json");
  Reference ref;
  ref.spp = spp;
  if (std::filesystem::exists(imagePath) && std::filesystem::exists(infoPath)) {
    try {
      ref.image = image::readPfm(imagePath);
      nlohmann::json info = nlohmann::json::parse(std::ifstream(infoPath));
      ref.seconds = info.at("seconds").get<double>();
      ref.noiseRelMse = info.at("noise_relmse").get<double>();
      ref.cached = ref.image.width == settings.width && ref.image.height == settings.height;
      if (ref.cached) return ref;
    } catch (const std::exception&) {
      // A damaged cache entry is rendered again below.
    }
  }
  auto start = std::chrono::steady_clock::now();
  image::LinearImage halves[2];
  for (int h = 0; h < 2; ++h) {
    progress.update(progressBase + h * 0.5, sceneName + ": reference");
    render::RenderSettings half = settings;
    half.seed = settings.seed + 1000003u * uint32_t(h + 1);  // never the methods' seed
    half.samplesPerFrame = 16;  // no learning: large batches, few submissions
    halves[h] = session::renderScene(ctx, asset, half, spp / 2, time).image;
  }
  ref.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ref.image = average(halves[0], halves[1]);
  ref.noiseRelMse = relativeMse(halves[0], halves[1]) / 4.0;
  std::filesystem::create_directories(cacheDir);
  image::writeImage(imagePath, ref.image);
  std::ofstream(infoPath) << nlohmann::json{
      {"seconds", ref.seconds},
      {"noise_relmse", ref.noiseRelMse},
      {"spp", spp},
      {"scene",
       sceneFile.string()}}.dump(2);
  return ref;
}

}  // namespace qlight::game::bench
