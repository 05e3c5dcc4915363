// The tracking study (`qlight bench --tracking`): how fast guiding follows a light that
// jumps and one that moves. Each frame is rendered on its own (1 spp by default, the
// accumulation restarted) and compared with a reference of that frame's light position;
// guiding that forgets (the demo's tracking), guiding that remembers everything (the
// learning rate vanishes as 1 / visits) and unguided rendering run the same frames, each
// over several seeds whose per-frame errors are averaged. Writes tracking.json and, by
// tools/tracking_plot.py, tracking.png.
#pragma once
#include <filesystem>
#include <nlohmann/json.hpp>

#include "engine/gpu/context.h"
#include "engine/guiding/guiding_settings.h"
#include "engine/render/render_settings.h"

namespace qlight::game::bench {

struct TrackingStudySettings {
  render::RenderSettings render;     // size and samples per frame of each frame
  guiding::GuidingSettings guiding;  // the guided methods' base settings
  float trackingHalfLife = 0.0f;     // the tracking method's: frames (0: not by time)
  float trackingForget = 4.0f;       // and halvings per scene radius a light moves
  uint32_t seeds = 8;                // runs per method, averaged per frame
  uint32_t frames = 180;             // 10 frames per second of scene time
  uint32_t referenceSpp = 128;       // per distinct light position
  std::filesystem::path cacheDir;    // references, as the bench caches them
};

// The study's scenes (door-ajar with an animated light): the equal-time bench leaves them
// out of its default list, as at time 0 they are the door-ajar scene again.
bool isTrackingStudyScene(const std::filesystem::path& file);

// Runs both cases and writes `outDir`/tracking.json; returns it.
nlohmann::json runTrackingStudy(const gpu::Context& ctx, const TrackingStudySettings& settings,
                                const std::filesystem::path& outDir);

}  // namespace qlight::game::bench
