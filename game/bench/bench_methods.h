// The methods the bench compares, and their interleaved run on one scene: each
// renders a frame in turn, so drifts in the machine's speed hit them alike,
// until every method has used the same render-time budget (equal time). The
// error against the reference is measured at checkpoints along the way (by
// samples and by time); measuring is not counted as render time.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "engine/gpu/context.h"
#include "engine/guiding/guiding_settings.h"
#include "engine/render/render_settings.h"
#include "engine/scene/scene_asset.h"
#include "game/bench/bench_metrics.h"
#include "game/progress_bar.h"

namespace qlight::game::bench {

struct MethodSpec {
  std::string name, label;
  guiding::GuidingSettings guiding;
  double freezeAfterShare = 0;  // > 0: learning stops after this share of the budget
};

// unguided, guided, guided with learned light selection, guided with learning frozen
// after a quarter of the budget, and deep Q guiding; all from the same base settings.
std::vector<MethodSpec> benchMethods(const guiding::GuidingSettings& base);

struct MethodResult {
  MethodSpec spec;
  std::vector<Checkpoint> checkpoints;
  std::vector<double> frameSeconds, emitterHitShare, meanPathLength;
  std::map<std::string, double> gpuMsTotal;  // per pass, over all frames
  uint32_t frames = 0, spp = 0, points = 0, sceneLights = 0;
  uint64_t rays = 0, guideMemoryBytes = 0;
  double seconds = 0;  // render time (the budget counts this)
  image::LinearImage finalImage;
};

struct MethodRunSettings {
  render::RenderSettings render;  // samplesPerFrame: the frame's batch
  double budgetSeconds = 1;
  float checkpointGrowth = 1.25f;  // spp between checkpoints grows by this factor
};

std::vector<MethodResult> runMethods(const gpu::Context& ctx, const scene::SceneAsset& asset,
                                     const std::vector<MethodSpec>& methods,
                                     const MethodRunSettings& settings,
                                     const image::LinearImage& reference, ProgressBar& progress,
                                     double progressBase, const std::string& sceneName);

}  // namespace qlight::game::bench
