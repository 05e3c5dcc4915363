// The converged image each method is compared against: unguided MIS at high
// spp, rendered in two halves with different seeds (their difference measures
// the reference's own noise), and cached on disk keyed by the scene file's
// bytes, the settings and the renderer's version, so a rerun reuses it.
#pragma once
#include <filesystem>
#include <string>

#include "engine/gpu/context.h"
#include "engine/render/render_settings.h"
#include "engine/scene/scene_asset.h"
#include "game/progress_bar.h"

namespace qlight::game::bench {

struct Reference {
  image::LinearImage image;
  uint32_t spp = 0;
  double seconds = 0;  // render time (0 when cached and not recorded)
  bool cached = false;
  double noiseRelMse = 0;  // relMSE of the reference itself: relMSE(half A, half B) / 4
};

// The renderer's version for cache keys: a hash of the path tracing shaders' SPIR-V and
// of a host-side version number bumped when the host changes what a render computes.
std::string rendererVersion();

// The scene at animation time `time`.
Reference loadOrRenderReference(const gpu::Context& ctx, const scene::SceneAsset& asset,
                                const std::filesystem::path& sceneFile,
                                const render::RenderSettings& settings, uint32_t spp,
                                const std::filesystem::path& cacheDir, ProgressBar& progress,
                                double progressBase, const std::string& sceneName,
                                float time = 0.0f);

}  // namespace qlight::game::bench
