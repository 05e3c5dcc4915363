#include "game/bench/bench_report.h"

#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace qlight::game::bench {
namespace {

namespace fs = std::filesystem;

// Non-finite figures become null (JSON has no NaN).
nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); }

double msPerSample(const MethodResult& m) { return m.spp ? 1e3 * m.seconds / m.spp : NAN; }

nlohmann::json methodJson(const MethodResult& m, uint32_t equalSpp, const std::string& pfm) {
  nlohmann::json checkpoints = nlohmann::json::array();
  for (const Checkpoint& c : m.checkpoints)
    checkpoints.push_back(
        {{"spp", c.spp}, {"seconds", number(c.seconds)}, {"relmse", number(c.relMse)}});
  nlohmann::json gpu = nlohmann::json::object();
  for (auto& [name, ms] : m.gpuMsTotal) gpu[name] = number(ms / std::max(1u, m.frames));
  std::optional<double> atEqual = relMseAtSpp(m.checkpoints, equalSpp);
  double finalRelMse = m.checkpoints.empty() ? NAN : m.checkpoints.back().relMse;
  return {
      {"name", m.spec.name},
      {"label", m.spec.label},
      {"checkpoints", checkpoints},
      {"frames",
       {{"seconds", m.frameSeconds},
        {"emitter_hit_share", m.emitterHitShare},
        {"mean_path_length", m.meanPathLength}}},
      {"gpu_ms_per_frame", gpu},
      {"final",
       {{"spp", m.spp},
        {"seconds", number(m.seconds)},
        {"relmse", number(finalRelMse)},
        {"rays_per_second", number(m.seconds > 0 ? double(m.rays) / m.seconds : NAN)},
        {"ms_per_spp", number(msPerSample(m))},
        {"pfm", pfm}}},
      {"equal_spp", {{"spp", equalSpp}, {"relmse", atEqual ? number(*atEqual) : nlohmann::json()}}},
      {"guide_memory_bytes", m.guideMemoryBytes},
      {"points", m.points}};
}

}  // namespace

nlohmann::json sceneJson(const SceneBench& s, const fs::path& outDir) {
  const fs::path imageDir = fs::path("images") / s.name;
  fs::create_directories(outDir / imageDir);
  image::writeImage(outDir / imageDir / "reference.pfm", s.reference.image);
  uint32_t equalSpp = UINT32_MAX;
  for (const MethodResult& m : s.methods) equalSpp = std::min(equalSpp, m.spp);

  nlohmann::json methods = nlohmann::json::array();
  for (const MethodResult& m : s.methods) {
    const fs::path pfm = imageDir / (m.spec.name + ".pfm");
    image::writeImage(outDir / pfm, m.finalImage);
    methods.push_back(methodJson(m, equalSpp, pfm.string()));
  }

  // Headline ratios against the unguided baseline (methods[0]).
  const MethodResult& base = s.methods.front();
  const double baseError = base.checkpoints.empty() ? NAN : base.checkpoints.back().relMse;
  const std::optional<double> baseAtEqual = relMseAtSpp(base.checkpoints, equalSpp);
  nlohmann::json timeTo = nlohmann::json::object(), extrapolated = nlohmann::json::object(),
                 equal = nlohmann::json::object(), equalNoiseless = nlohmann::json::object(),
                 perSample = nlohmann::json::object();
  // A method's relMSE against the reference is its own plus the reference's (independent
  // noise adds), which pulls every equal-spp ratio toward 1; the time to the baseline's
  // error is unaffected (the same offset on both sides). Without the reference's share the
  // ratio compares the methods' own errors, given while that share is under half the
  // baseline's error (beyond it, the difference is itself mostly noise).
  const double noise = s.reference.noiseRelMse;
  for (size_t i = 1; i < s.methods.size(); ++i) {
    const MethodResult& m = s.methods[i];
    std::optional<TimeToError> t = timeToReach(m.checkpoints, baseError);
    timeTo[m.spec.name] =
        t && base.seconds > 0 ? number(t->seconds / base.seconds) : nlohmann::json();
    extrapolated[m.spec.name] = t ? t->extrapolated : true;
    std::optional<double> atEqual = relMseAtSpp(m.checkpoints, equalSpp);
    equal[m.spec.name] =
        atEqual && baseAtEqual ? number(*atEqual / *baseAtEqual) : nlohmann::json();
    equalNoiseless[m.spec.name] = atEqual && baseAtEqual && noise < 0.5 * *baseAtEqual
                                      ? number((*atEqual - noise) / (*baseAtEqual - noise))
                                      : nlohmann::json();
    perSample[m.spec.name] = number(msPerSample(m) / msPerSample(base));
  }
  return {{"name", s.name},
          {"file", s.file.string()},
          {"triangles", s.triangles},
          {"lights", s.lights},
          {"reference",
           {{"pfm", (imageDir / "reference.pfm").string()},
            {"spp", s.reference.spp},
            {"seconds", number(s.reference.seconds)},
            {"cached", s.reference.cached},
            {"noise_relmse", number(s.reference.noiseRelMse)}}},
          {"methods", methods},
          {"headline",
           {{"time_to_unguided_error", timeTo},
            {"time_to_unguided_error_extrapolated", extrapolated},
            {"equal_spp_relmse_ratio", equal},
            {"equal_spp_relmse_ratio_without_reference_noise", equalNoiseless},
            {"time_per_sample_ratio", perSample}}}};
}

void runReportScript(const std::string& scriptName, const fs::path& outDir) {
  const fs::path script = fs::path(QLIGHT_SOURCE_DIR) / "tools" / scriptName;
  // Debian's python3 has python3-matplotlib; another python3 earlier on PATH may not.
  const std::string python = fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  const std::string command = python + " '" + script.string() + "' '" + outDir.string() + "'";
  if (std::system(command.c_str()) != 0)
    throw std::runtime_error("bench: the report and plots failed (" + command +
                             "; needs python3-matplotlib); the JSON is written");
}

void writeReport(const fs::path& outDir) { runReportScript("bench_report.py", outDir); }

}  // namespace qlight::game::bench
