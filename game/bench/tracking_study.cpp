#include "game/bench/tracking_study.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "engine/gltf/gltf_loader.h"
#include "engine/session/renderer.h"
#include "engine/session/stats_json.h"
#include "game/bench/bench_metrics.h"
#include "game/bench/bench_reference.h"
#include "game/progress_bar.h"
#include "game/shipped_scenes.h"

namespace qlight::game::bench {
namespace {

namespace fs = std::filesystem;

constexpr float kFps = 10.0f;  // scene time per frame: 0.1 s
// "Back to steady" is judged on the mean of the last few frames (a single frame's relMSE
// at 1 spp swings with its fireflies), against the steady level the light's new position
// reaches: the tracking method's mean over the frames before the next event.
constexpr uint32_t kSmoothFrames = 5, kSteadyFrames = 20;
constexpr double kBackWithin = 1.25;    // issue 12's criterion
constexpr uint32_t kWarmupFrames = 20;  // learning from nothing is not tracking

struct TrackingCase {
  const char* name;
  const char* scene;  // shipped scene
  const char* what;
  // Frames with the same light position share a reference: the time that stands for t.
  float (*lightTime)(float t);
  std::vector<uint32_t> jumps;  // frames where the light jumps (none: it glides)
};

// door_ajar_jumping_light: the panel stands in room B's far corner for 6 s, then by the
// door for 6 s, in a loop; door_ajar_moving_light glides between them and back in 8 s.
const TrackingCase kCases[] = {
    {"jump",
     "door_ajar_jumping_light.gltf",
     "the light jumps every 6 s",
     [](float t) { return std::fmod(t, 12.0f) < 6.0f ? 0.0f : 6.0f; },
     {60, 120}},
    {"moving",
     "door_ajar_moving_light.gltf",
     "the light glides through room B in 8 s",
     [](float t) { return std::fmod(t, 8.0f); },
     {}},
};

struct TrackingMethod {
  std::string name, label;
  guiding::GuidingSettings guiding;
  uint32_t firstSeed = 1;
};

// Unguided again with other seeds: its worst ratio to unguided is what the measure's own
// noise alone gives, the yardstick for "never worse than unguided".
constexpr uint32_t kNoiseSeedOffset = 1000;

std::vector<TrackingMethod> trackingMethods(const TrackingStudySettings& s) {
  guiding::GuidingSettings tracking = s.guiding, rememberAll = s.guiding, off = s.guiding;
  tracking.enabled = rememberAll.enabled = true;
  tracking.halfLifeFrames = s.trackingHalfLife;
  tracking.forgetOnLightMove = s.trackingForget;
  rememberAll.halfLifeFrames = 0.0f;
  rememberAll.forgetOnLightMove = 0.0f;
  off.enabled = false;
  char label[96];
  if (s.trackingHalfLife > 0 && s.trackingForget > 0)
    std::snprintf(label, sizeof(label), "guided, half-life %.0f frames, %.1f halvings/radius moved",
                  s.trackingHalfLife, s.trackingForget);
  else if (s.trackingHalfLife > 0)
    std::snprintf(label, sizeof(label), "guided, half-life %.0f frames", s.trackingHalfLife);
  else
    std::snprintf(label, sizeof(label), "guided, %.1f halvings per radius a light moves",
                  s.trackingForget);
  return {{"tracking", label, tracking},
          {"remember_all", "guided, remembers everything (rate 1/visits)", rememberAll},
          {"unguided", "unguided", off},
          {"unguided_other_seeds", "unguided, other seeds (the measure's noise)", off,
           1 + kNoiseSeedOffset}};
}

float frameTime(uint32_t frame) { return float(frame) / kFps; }
// The reference a frame is compared with, as the frame number of its light time.
uint32_t referenceKey(const TrackingCase& tc, uint32_t frame) {
  return uint32_t(std::lround(tc.lightTime(frameTime(frame)) * kFps));
}

// Mean of v over [first, last), clipped to v's size.
double meanOver(const std::vector<double>& v, size_t first, size_t last) {
  last = std::min(last, v.size());
  if (first >= last) return NAN;
  double sum = 0;
  for (size_t i = first; i < last; ++i) sum += v[i];
  return sum / double(last - first);
}

// The trailing mean of kSmoothFrames frames, never reaching back past `segmentStart`.
std::vector<double> smoothed(const std::vector<double>& v, const std::vector<uint32_t>& jumps) {
  std::vector<double> out(v.size());
  for (size_t f = 0; f < v.size(); ++f) {
    size_t start = f + 1 >= kSmoothFrames ? f + 1 - kSmoothFrames : 0;
    for (uint32_t j : jumps)
      if (j <= f) start = std::max<size_t>(start, j);
    out[f] = meanOver(v, start, f + 1);
  }
  return out;
}

nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nullptr; }

}  // namespace

bool isTrackingStudyScene(const fs::path& file) {
  for (const TrackingCase& tc : kCases)
    if (file.filename() == tc.scene) return true;
  return false;
}

nlohmann::json runTrackingStudy(const gpu::Context& ctx, const TrackingStudySettings& settings,
                                const fs::path& outDir) {
  const std::vector<TrackingMethod> methods = trackingMethods(settings);
  const uint32_t frames = settings.frames;
  render::RenderSettings referenceSettings = settings.render;
  referenceSettings.estimator = render::Estimator::Mis;
  referenceSettings.russianRoulette = true;
  referenceSettings.seed = 1;

  // Progress in frames; a reference counts as many frames as its 16-spp batches.
  const double referenceWeight = std::max(1.0, settings.referenceSpp / 16.0);
  double total = 0;
  std::vector<std::map<uint32_t, int>> lightTimes(std::size(kCases));
  for (size_t c = 0; c < std::size(kCases); ++c) {
    for (uint32_t f = 0; f < frames; ++f) lightTimes[c][referenceKey(kCases[c], f)] = 0;
    total += referenceWeight * double(lightTimes[c].size()) +
             double(methods.size() * settings.seeds * frames);
  }
  ProgressBar progress(total, "qlight bench");
  double done = 0;

  nlohmann::json cases = nlohmann::json::array();
  for (size_t c = 0; c < std::size(kCases); ++c) {
    const TrackingCase& tc = kCases[c];
    const std::string file = resolveScene(tc.scene);
    const scene::SceneAsset asset = gltf::loadGltf(file);
    std::map<uint32_t, image::LinearImage> references;
    for (const auto& [key, unused] : lightTimes[c]) {
      references[key] =
          loadOrRenderReference(ctx, asset, file, referenceSettings, settings.referenceSpp,
                                settings.cacheDir, progress, done,
                                std::string(tc.name) + ": references", frameTime(key))
              .image;
      done += referenceWeight;
    }

    std::vector<std::vector<double>> errors(methods.size(), std::vector<double>(frames, 0.0));
    for (size_t m = 0; m < methods.size(); ++m) {
      for (uint32_t seed = 0; seed < settings.seeds; ++seed) {
        render::RenderSettings rs = settings.render;
        rs.seed = methods[m].firstSeed + seed;
        rs.temporalBlend = 0.0f;
        guiding::GuidingSettings g = methods[m].guiding;
        g.seed = rs.seed;
        session::Renderer renderer(ctx, asset, rs, g);
        for (uint32_t f = 0; f < frames; ++f) {
          progress.update(done, std::string(tc.name) + ": " + methods[m].name);
          renderer.tracer().resetAccumulation();  // the frame's own samples only
          renderer.renderFrame(frameTime(f));
          errors[m][f] +=
              relativeMse(renderer.tracer().readImage(), references.at(referenceKey(tc, f))) /
              double(settings.seeds);
          done += 1;
        }
      }
    }

    // The measures: recovery after each jump, the mean and the worst (smoothed) ratio to
    // unguided after the warm-up.
    const size_t tracking = 0, unguided = 2;
    std::vector<std::vector<double>> smooth;
    for (const auto& e : errors) smooth.push_back(smoothed(e, tc.jumps));
    nlohmann::json methodEntries = nlohmann::json::array();
    for (size_t m = 0; m < methods.size(); ++m) {
      nlohmann::json recoveries = nlohmann::json::array();
      for (size_t j = 0; j < tc.jumps.size(); ++j) {
        const uint32_t jump = tc.jumps[j];
        const uint32_t next = j + 1 < tc.jumps.size() ? tc.jumps[j + 1] : frames;
        const double steady =
            meanOver(errors[tracking], next - std::min(next, kSteadyFrames), next);
        std::optional<uint32_t> back;
        for (uint32_t f = jump; f < next && !back; ++f)
          if (smooth[m][f] <= kBackWithin * steady) back = f - jump;
        recoveries.push_back(
            {{"jump_frame", jump},
             {"steady_rel_mse", number(steady)},
             {"frames_to_within_1_25", back ? nlohmann::json(*back) : nullptr},
             {"jump_frame_ratio_to_unguided", number(errors[m][jump] / errors[unguided][jump])},
             {"first_10_frames_ratio_to_unguided",
              number(meanOver(errors[m], jump, jump + 10) /
                     meanOver(errors[unguided], jump, jump + 10))},
             {"peak_rel_mse",
              number(*std::max_element(smooth[m].begin() + jump, smooth[m].begin() + next))}});
      }
      double worst = 0;
      for (uint32_t f = kWarmupFrames; f < frames; ++f)
        worst = std::max(worst, smooth[m][f] / smooth[unguided][f]);
      const double mean = meanOver(errors[m], kWarmupFrames, frames);
      methodEntries.push_back(
          {{"name", methods[m].name},
           {"label", methods[m].label},
           {"half_life_frames", methods[m].guiding.enabled
                                    ? nlohmann::json(methods[m].guiding.halfLifeFrames)
                                    : nullptr},
           {"forget_on_light_move", methods[m].guiding.enabled
                                        ? nlohmann::json(methods[m].guiding.forgetOnLightMove)
                                        : nullptr},
           {"rel_mse", errors[m]},
           {"mean_rel_mse", number(mean)},
           {"mean_ratio_to_unguided",
            number(mean / meanOver(errors[unguided], kWarmupFrames, frames))},
           {"worst_smoothed_ratio_to_unguided", number(worst)},
           {"recovery", recoveries}});
    }
    const fs::path relative = fs::relative(file, QLIGHT_SOURCE_DIR);
    cases.push_back(
        {{"name", tc.name},
         {"scene", relative.empty() || *relative.begin() == ".." ? file : relative.string()},
         {"what", tc.what},
         {"jump_frames", tc.jumps},
         {"references", references.size()},
         {"methods", methodEntries}});
  }
  progress.finish();
  nlohmann::json j = {{"device", ctx.deviceName()},
                      {"width", settings.render.width},
                      {"height", settings.render.height},
                      {"spp_per_frame", settings.render.samplesPerFrame},
                      {"seeds", settings.seeds},
                      {"frames", frames},
                      {"fps", kFps},
                      {"reference_spp", settings.referenceSpp},
                      {"smooth_frames", kSmoothFrames},
                      {"steady_frames", kSteadyFrames},
                      {"warmup_frames", kWarmupFrames},
                      {"cases", cases}};
  fs::create_directories(outDir);
  session::writeJson(outDir / "tracking.json", j);
  return j;
}

}  // namespace qlight::game::bench
