#include "game/bench/bench_command.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <optional>

#include "engine/gltf/gltf_loader.h"
#include "engine/session/stats_json.h"
#include "game/bench/bench_report.h"
#include "game/bench/tracking_study.h"
#include "game/cli_options.h"
#include "game/context_setup.h"
#include "game/demo_command.h"
#include "game/shipped_scenes.h"

namespace qlight::game {
namespace {

namespace fs = std::filesystem;
using namespace bench;

struct BenchArgs {
  bool quick = false;
  std::vector<std::string> scenes;  // empty: every shipped scene
  std::string out = "out/bench";
  std::string cache;                    // empty: $XDG_CACHE_HOME/qlight or ~/.cache/qlight
  std::optional<double> budgetSeconds;  // per method and scene; default: the mode's
  uint32_t referenceSpp = 0;
  uint32_t width = 0, height = 0;
  uint32_t sppPerFrame = 0;  // 0: the mode's (bench 2, tracking 1)
  std::string traversal;     // bench_traversal_vs_embree's JSON to include
  bool report = true;
  bool tracking = false;  // the tracking study instead of the equal-time comparison
  uint32_t seeds = 0;     // tracking: runs per method (quick 2, full 8)
  bool trackingHalfLifeSet = false, trackingForgetSet = false;  // else the demo's
  // The methods' renderer and guiding settings (each method sets guiding on or off and
  // light learning itself).
  render::RenderSettings render;
  guiding::GuidingSettings guiding;
  GuidingCli guidingCli;
};

// The quick mode finishes in about a minute on lavapipe (2 cores), the full one in well
// under an hour for the shipped scenes.
void applyModeDefaults(BenchArgs& a) {
  if (!a.budgetSeconds) a.budgetSeconds = a.quick ? 2.5 : 40.0;
  if (a.referenceSpp == 0) a.referenceSpp = a.quick ? 256 : 2048;
  if (a.width == 0) a.width = a.quick ? 96 : 256;
  if (a.height == 0) a.height = a.quick ? 54 : 144;
  if (a.sppPerFrame == 0) a.sppPerFrame = 2;
}

fs::path cacheDirectory(const BenchArgs& a) {
  if (!a.cache.empty()) return a.cache;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    return fs::path(xdg) / "qlight" / "references";
  if (const char* home = std::getenv("HOME"); home && *home)
    return fs::path(home) / ".cache" / "qlight" / "references";
  return fs::path(a.out) / "reference-cache";
}

// Bad input gets one line before any rendering.
void validate(const BenchArgs& a, const std::vector<std::string>& scenes) {
  if (!(*a.budgetSeconds > 0) || !std::isfinite(*a.budgetSeconds))
    throw std::invalid_argument("bench: the time budget must be a positive number of seconds");
  if (a.referenceSpp < 2) throw std::invalid_argument("bench: the reference needs at least 2 spp");
  for (const std::string& s : scenes)
    if (!fs::is_regular_file(s)) throw std::invalid_argument("bench: no scene file " + s);
  std::error_code ec;
  fs::create_directories(a.out, ec);
  std::ofstream probe(fs::path(a.out) / ".write-test");
  if (ec || !probe)
    throw std::invalid_argument("bench: cannot write to the output folder " + a.out);
  probe.close();
  fs::remove(fs::path(a.out) / ".write-test");
}

// The traversal comparison's figures as the report reads them (scene, ray kind, both
// tracers' rays per second, their ratio and the disagreeing rays).
nlohmann::json traversalEntry(const std::string& file) {
  if (file.empty()) return nullptr;
  nlohmann::json in;
  try {
    in = nlohmann::json::parse(std::ifstream(file));
  } catch (const std::exception& e) {
    throw std::invalid_argument("bench: " + file + " is not a traversal result: " + e.what());
  }
  nlohmann::json scenes = nlohmann::json::array();
  for (const auto& s : in.at("scenes")) {
    nlohmann::json kinds = nlohmann::json::array();
    for (const auto& set : s.at("sets"))
      kinds.push_back({{"kind", set.at("kind")},
                       {"qlight_mrays", set.at("qlight_mrays_per_s")},
                       {"embree_mrays", set.at("embree_mrays_per_s")},
                       {"ratio", set.at("ratio_qlight_to_embree")},
                       {"mismatches", set.at("agreement").at("mismatches")},
                       {"rays", set.at("rays")}});
    const std::string name = fs::path(s.at("name").get<std::string>()).stem().string();
    scenes.push_back({{"scene", name}, {"triangles", s.at("triangles")}, {"kinds", kinds}});
  }
  return {{"scenes", scenes}};
}

std::string isoDate() {
  std::time_t now = std::time(nullptr);
  char text[32];
  std::strftime(text, sizeof(text), "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return text;
}

// The tracking study: 1 spp per frame (a realtime frame), the demo's forgetting.
int runTracking(BenchArgs a, const CommonOptions& common) {
  TrackingStudySettings t;
  t.render = a.render;
  t.render.width = a.width != 0 ? a.width : a.quick ? 64 : 128;
  t.render.height = a.height != 0 ? a.height : a.quick ? 36 : 72;
  t.render.samplesPerFrame = a.sppPerFrame != 0 ? a.sppPerFrame : 1;
  t.guiding = a.guiding;
  t.trackingHalfLife = a.trackingHalfLifeSet ? a.guiding.halfLifeFrames : kDemoHalfLifeFrames;
  t.trackingForget = a.trackingForgetSet ? a.guiding.forgetOnLightMove : kDemoForgetOnLightMove;
  t.seeds = a.seeds != 0 ? a.seeds : a.quick ? 2 : 8;
  t.referenceSpp = a.referenceSpp != 0 ? a.referenceSpp : a.quick ? 32 : 128;
  t.cacheDir = cacheDirectory(a);
  a.budgetSeconds = 1.0;  // unused by the study
  a.referenceSpp = t.referenceSpp;
  validate(a, {});
  auto ctx = createContext(common, /*windowed=*/false);
  const nlohmann::json j = runTrackingStudy(*ctx, t, a.out);
  if (a.report) runReportScript("tracking_plot.py", a.out);
  std::printf("qlight bench --tracking: %ux%u, %u spp per frame, %u seeds; %s/tracking.json\n",
              t.render.width, t.render.height, t.render.samplesPerFrame, t.seeds, a.out.c_str());
  for (const auto& c : j["cases"])
    for (const auto& m : c["methods"]) {
      std::printf("  %-7s %-13s mean relMSE %s of unguided's", c["name"].get<std::string>().c_str(),
                  m["name"].get<std::string>().c_str(), m["mean_ratio_to_unguided"].dump().c_str());
      for (const auto& r : m["recovery"])
        std::printf(", jump at %s: back in %s frames", r["jump_frame"].dump().c_str(),
                    r["frames_to_within_1_25"].dump().c_str());
      std::printf("\n");
    }
  return finishContext(*ctx);
}

int runBench(BenchArgs a, const CommonOptions& common) {
  if (a.tracking) return runTracking(a, common);
  applyModeDefaults(a);
  std::vector<std::string> scenes;
  for (const std::string& s : a.scenes) scenes.push_back(resolveScene(s));
  if (scenes.empty())
    for (const std::string& s : shippedScenes())
      if (!isTrackingStudyScene(s)) scenes.push_back(s);
  validate(a, scenes);
  const nlohmann::json traversal = traversalEntry(a.traversal);  // fails before rendering
  auto ctx = createContext(common, /*windowed=*/false);

  render::RenderSettings settings = a.render;
  settings.width = a.width;
  settings.height = a.height;
  settings.samplesPerFrame = a.sppPerFrame;
  MethodRunSettings run;
  run.render = settings;
  run.budgetSeconds = *a.budgetSeconds;
  const std::vector<MethodSpec> methods = benchMethods(a.guiding);
  // The reference is the same image by its lowest-variance estimator, whatever the methods use.
  render::RenderSettings referenceSettings = settings;
  referenceSettings.estimator = render::Estimator::Mis;
  referenceSettings.russianRoulette = true;

  // Progress in units of work: a reference counts 1 (0 when cached), methods their budget.
  const double perScene = 1.0 + *a.budgetSeconds * double(methods.size());
  ProgressBar progress(perScene * double(scenes.size()), "qlight bench");
  nlohmann::json sceneEntries = nlohmann::json::array();
  for (size_t i = 0; i < scenes.size(); ++i) {
    const std::string name = fs::path(scenes[i]).stem().string();
    const scene::SceneAsset asset = gltf::loadGltf(scenes[i]);
    SceneBench sb;
    sb.name = name;
    // Shipped scenes are named relative to the repository, so reports read the same anywhere.
    const fs::path relative = fs::relative(scenes[i], QLIGHT_SOURCE_DIR);
    sb.file = relative.empty() || *relative.begin() == ".." ? fs::path(scenes[i]) : relative;
    for (const scene::MeshAsset& m : asset.meshes) sb.triangles += m.triangleCount();
    const double base = perScene * double(i);
    sb.reference = loadOrRenderReference(*ctx, asset, scenes[i], referenceSettings, a.referenceSpp,
                                         cacheDirectory(a), progress, base, name);
    sb.methods =
        runMethods(*ctx, asset, methods, run, sb.reference.image, progress, base + 1.0, name);
    sb.lights = sb.methods.front().sceneLights;
    sceneEntries.push_back(sceneJson(sb, a.out));
  }
  progress.finish();

  nlohmann::json j = {
      {"mode", a.quick ? "quick" : "full"},
      {"device", ctx->deviceName()},
      {"width", a.width},
      {"height", a.height},
      {"spp_per_frame", a.sppPerFrame},
      {"time_budget_seconds", *a.budgetSeconds},
      {"reference_spp", a.referenceSpp},
      {"renderer_version", rendererVersion()},
      {"date", isoDate()},
      {"settings",
       {{"estimator", settings.estimator == render::Estimator::Mis        ? "mis"
                      : settings.estimator == render::Estimator::BsdfOnly ? "bsdf"
                                                                          : "nee"},
        {"russian_roulette", settings.russianRoulette},
        {"max_depth", settings.maxDepth},
        {"strata", std::to_string(a.guiding.rows) + "x" + std::to_string(a.guiding.cols)},
        {"directions", a.guiding.directions == guiding::DirectionModel::Tree ? "tree" : "strata"},
        {"tree_nodes", a.guiding.treeNodes},
        {"tree_split", a.guiding.treeSplitShare},
        {"select_probability", a.guiding.selectProbability},
        {"confidence_updates", a.guiding.confidenceUpdates},
        {"nee_min_probability", a.guiding.neeMinProbability},
        {"guided_roulette", a.guiding.guidedRoulette},
        {"learning_target",
         a.guiding.target == guiding::LearningTarget::Returns ? "returns" : "td"},
        {"alpha_min", a.guiding.alphaMin},
        {"alpha_max", a.guiding.alphaMax},
        {"point_budget", a.guiding.pointBudget == 0 ? nlohmann::json("auto")
                                                    : nlohmann::json(a.guiding.pointBudget)}}},
      {"scenes", sceneEntries},
      {"traversal", traversal}};
  session::writeJson(fs::path(a.out) / "bench.json", j);
  if (a.report) writeReport(a.out);
  std::printf("qlight bench: %zu scenes, %zu methods, %.1f s each; %s/report.md\n", scenes.size(),
              methods.size(), *a.budgetSeconds, a.out.c_str());
  for (const auto& s : sceneEntries) {
    std::printf("  %-16s", s["name"].get<std::string>().c_str());
    for (const auto& [method, ratio] : s["headline"]["time_to_unguided_error"].items())
      std::printf("  %s: time to unguided's error %s", method.c_str(),
                  ratio.is_null()
                      ? "n/a"
                      : (std::to_string(ratio.get<double>()).substr(0, 5) + "x").c_str());
    std::printf("\n");
  }
  return finishContext(*ctx);
}

}  // namespace

std::function<int()> addBenchCommand(CLI::App& app, const CommonOptions& common) {
  auto args = std::make_shared<BenchArgs>();
  CLI::App* cmd =
      app.add_subcommand("bench", "guided vs unguided at equal time and equal samples, with plots");
  cmd->add_flag("--quick", args->quick, "about a minute on lavapipe (small images, short budgets)");
  cmd->add_option(
      "--scene", args->scenes,
      "glTF scene or shipped name (repeat; default: every shipped scene but the tracking "
      "study's)");
  cmd->add_option("--out", args->out, "output folder (bench.json, report.md, plots/, images/)")
      ->capture_default_str();
  cmd->add_option("--budget", args->budgetSeconds,
                  "render seconds per method and scene (quick 2.5, full 40)");
  cmd->add_option("--reference-spp", args->referenceSpp,
                  "reference samples per pixel (quick 256, full 2048; tracking 32, 128)");
  cmd->add_option("--width", args->width, "image width (quick 96, full 256; tracking 64, 128)")
      ->check(CLI::Range(1, 16384));
  cmd->add_option("--height", args->height, "image height (quick 54, full 144; tracking 36, 72)")
      ->check(CLI::Range(1, 16384));
  cmd->add_option("--spp-per-frame", args->sppPerFrame,
                  "samples per pixel per frame, learning runs between frames (2; tracking 1)")
      ->check(CLI::Range(1, 4096));
  cmd->add_option("--cache", args->cache,
                  "reference cache folder (default ~/.cache/qlight/references)");
  addTracingOptions(*cmd, args->render);  // the reference keeps MIS + RR
  addGuidingOptions(*cmd, args->guiding, args->guidingCli);
  cmd->add_option("--traversal", args->traversal,
                  "include this bench_traversal_vs_embree --out JSON in the report");
  cmd->add_flag("!--no-report", args->report, "skip tools/bench_report.py (JSON and images only)");
  cmd->add_flag("--tracking", args->tracking,
                "the tracking study instead: a jumping and a moving light, per-frame error "
                "(tracking.json, tracking.png)");
  cmd->add_option("--seeds", args->seeds, "tracking: runs per method (quick 2, full 8)")
      ->check(CLI::Range(1, 1000));
  return [cmd, args, &common]() -> int {
    if (!cmd->parsed()) return -1;
    finishGuidingOptions(args->guidingCli, args->guiding, args->render);
    args->trackingHalfLifeSet = cmd->count("--half-life") > 0;
    args->trackingForgetSet = cmd->count("--forget-on-light-move") > 0;
    return runBench(*args, common);
  };
}

}  // namespace qlight::game
