#include "engine/session/stats_json.h"

#include <fstream>
#include <stdexcept>

namespace qlight::session {

nlohmann::json statsToJson(const RenderStats& s) {
  const render::FrameCounters& c = s.counters;
  double paths = double(std::max<uint64_t>(c.paths, 1));
  nlohmann::json j;
  j["width"] = s.width;
  j["height"] = s.height;
  j["spp"] = s.spp;
  j["frames"] = s.frames;
  j["seconds"] = s.seconds;
  j["rays"] = c.rays;
  j["shadow_rays"] = c.shadowRays;
  j["rays_per_second"] = s.seconds > 0 ? double(c.rays) / s.seconds : 0.0;
  j["paths"] = c.paths;
  j["emitter_hit_share"] = double(c.emitterHits) / paths;
  j["mean_path_length"] = double(c.pathVertices) / paths;
  j["invalid_samples"] = c.invalidSamples;
  j["device"] = s.device;
  j["trace_kernel"] = s.traceInShade ? "fused" : "separate";
  j["lights"] = s.lights;
  j["fallback_sky"] = s.fallbackSky;
  j["glow_maps_only"] = s.glowMapsOnly;
  j["environment_light"] = s.environmentLight;
  j["triangles"] = s.triangles;
  j["scene_gpu_bytes"] = s.sceneGpuBytes;
  j["blas_build_seconds"] = s.blasBuildSeconds;
  j["scene_build_seconds"] = s.sceneBuildSeconds;
  nlohmann::json gpu = nlohmann::json::object();
  double total = 0;
  for (auto& [name, ms] : s.gpuMs) {
    gpu[name] = {{"total_ms", ms}, {"ms_per_frame", ms / std::max(1u, s.frames)}};
    total += ms;
  }
  j["gpu_ms"] = gpu;
  j["gpu_ms_total"] = total;
  j["guiding"] = !s.guided ? "off" : s.deepQ ? "dqn" : "q";
  j["covered_vertices"] = c.coveredVertices;
  if (s.guided) {
    const auto& g = s.guidingStats;
    double guidingMs = 0;
    for (auto& [name, ms] : s.gpuMs)
      if (name.rfind("guiding", 0) == 0 || name.rfind("prefix_sum", 0) == 0 ||
          name.rfind("dqn.", 0) == 0)
        guidingMs += ms;
    j["guiding_stats"] = {{"points", g.points},
                          {"strata", g.strata},
                          {"lights_learned", g.lightsLearned},
                          {"rejection_min", g.rejectionMin},
                          {"rejection_max", g.rejectionMax},
                          {"search_radius", g.searchRadius},
                          {"spawned_points", g.spawnedPoints},
                          {"point_generation_seconds", s.pointGenerationSeconds},
                          {"learning_gpu_ms_per_frame", guidingMs / std::max(1u, s.frames)}};
  }
  j["emitter_hit_share_by_frame"] = s.emitterHitShareByFrame;
  j["mean_path_length_by_frame"] = s.pathLengthByFrame;
  return j;
}

void writeJson(const std::filesystem::path& path, const nlohmann::json& json) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path.string() + ": cannot open for writing");
  out << json.dump(2) << "\n";
  if (!out) throw std::runtime_error(path.string() + ": write failed");
}

}  // namespace qlight::session
