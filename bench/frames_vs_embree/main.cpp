// bench_frames_vs_embree: qlight's whole path-tracing frames (the default
// renderer unguided: NEE + MIS + Russian roulette) against a plain single-ray
// Embree path tracer with the same light transport on the same CPU cores, and
// against qlight's own traversal-only rate on the same scene. The two figures
// of issue 10's frame goal: frame rays/s over Embree's (goal 0.4x) and over the
// kernel's traversal alone (goal 0.6x). Usage: see kUsage.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "bench/frames_vs_embree/embree_path_tracer.h"
#include "bench/traversal_vs_embree/embree_tracer.h"
#include "bench/traversal_vs_embree/qlight_tracer.h"
#include "bench/traversal_vs_embree/ray_sets.h"
#include "bench/traversal_vs_embree/report.h"
#include "bench/traversal_vs_embree/world_scene.h"
#include "engine/gpu/context.h"
#include "engine/session/offline_render.h"
#include "shaders/shared/sampling.h"

namespace {

using namespace qlight;
using namespace qlight::bench;
namespace fs = std::filesystem;
using nlohmann::json;

constexpr const char* kName = "bench_frames_vs_embree";
constexpr const char* kUsage =
    "usage: bench_frames_vs_embree [SCENE.gltf ...] [--width W] [--height H] [--spp N]\n"
    "                              [--reps N] [--threads N] [--out FILE.json] [--quick]\n"
    "  SCENE      a glTF path, or a file name in assets/ or the build's generated assets\n"
    "             (default: door_ajar, cornell_box, corridor and furnished_room)\n"
    "  --width/--height  render size (default 256x144, the bench's)\n"
    "  --spp N    samples per pixel of each render (default 16; qlight in frames of 2)\n"
    "  --reps N   renders per side, alternated (default 3; medians reported)\n"
    "  --threads  Embree's threads (default: LP_NUM_THREADS, else the core count, as lavapipe)\n"
    "  --quick    128x72, 8 spp, 2 reps\n"
    "  --out      also write every figure as JSON\n";

const char* kDefaultScenes[] = {"door_ajar.gltf", "cornell_box.gltf", "corridor.gltf",
                                "furnished_room.gltf"};
constexpr uint32_t kSeed = 20240611;
constexpr uint32_t kSamplesPerFrame = 2;
constexpr double kMeanSigmas = 5.0;  // image means further apart fail the run
constexpr uint32_t kTraversalWidth = 640, kTraversalHeight = 360;

struct Options {
  std::vector<fs::path> scenes;
  uint32_t width = 256, height = 144, spp = 16, reps = 3;
  unsigned threads = 0;
  std::string out;
};

[[noreturn]] void fail(const std::string& message, int code = 2) {
  std::fprintf(stderr, "%s: %s\n", kName, message.c_str());
  std::exit(code);
}

// A path, or a file name in assets/ or in the build's generated assets (the furnished room).
std::optional<fs::path> findScene(const std::string& arg) {
  fs::path p(arg);
  if (fs::is_regular_file(p)) return p;
  for (const fs::path dir :
       {fs::path(QLIGHT_SOURCE_DIR) / "assets", fs::path(QLIGHT_GENERATED_ASSETS_DIR)})
    if (fs::is_regular_file(dir / p)) return dir / p;
  return std::nullopt;
}

Options parse(int argc, char** argv) {
  Options o;
  bool quick = false;
  std::vector<std::string> sceneArgs;
  CLI::App app(kUsage, kName);
  app.add_option("scenes", sceneArgs, "scenes");
  CLI::Option* width = app.add_option("--width", o.width)->check(CLI::Range(1u, 4096u));
  CLI::Option* height = app.add_option("--height", o.height)->check(CLI::Range(1u, 4096u));
  CLI::Option* spp = app.add_option("--spp", o.spp)->check(CLI::Range(1u, 65536u));
  CLI::Option* reps = app.add_option("--reps", o.reps)->check(CLI::Range(1u, 100u));
  app.add_option("--threads", o.threads)->check(CLI::Range(1u, 1024u));
  app.add_flag("--quick", quick);
  app.add_option("--out", o.out);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::fputs(kUsage, stdout);
    std::exit(0);
  } catch (const CLI::ParseError& e) {
    fail(std::string(e.what()) + " (see --help)");
  }
  for (const std::string& a : sceneArgs) {
    std::optional<fs::path> p = findScene(a);
    if (!p) fail("no scene file '" + a + "' (neither a path nor a file in assets/)");
    o.scenes.push_back(*p);
  }
  const bool sized = width->count() + height->count() > 0, sampled = spp->count() > 0,
             repeated = reps->count() > 0;
  if (quick) {
    if (!sized) o.width = 128, o.height = 72;
    if (!sampled) o.spp = 8;
    if (!repeated) o.reps = 2;
  }
  if (o.spp % kSamplesPerFrame != 0) fail("--spp must be even (qlight renders frames of 2)");
  if (o.scenes.empty())
    for (const char* s : kDefaultScenes) {
      std::optional<fs::path> p = findScene(s);
      if (p)
        o.scenes.push_back(*p);
      else
        std::fprintf(stderr, "%s: %s not found (build the generated_assets target): skipped\n",
                     kName, s);
    }
  if (o.threads == 0) {
    const char* lp = std::getenv("LP_NUM_THREADS");
    o.threads = lp && std::atoi(lp) > 0 ? unsigned(std::atoi(lp))
                                        : std::max(1u, std::thread::hardware_concurrency());
  }
  return o;
}

// One render of either side.
struct Run {
  double wallMs = 0;
  uint64_t rays = 0, shadowRays = 0, paths = 0;
  double gpuMs = 0;  // qlight: the frames' passes from their timestamps
  double mrays() const { return rays / wallMs * 1e-3; }
};

// The image's mean luminance and its standard error.
struct ImageMean {
  double mean = 0, standardError = 0;
};

struct SceneFigures {
  std::string name;
  uint64_t triangles = 0;
  std::vector<Run> qlight, embree;
  ImageMean qlightMean, embreeMean;
  // qlight's traversal alone (trace_rays.comp over the bench's ray sets), GPU ms per ray kind.
  double cameraNsPerRay = 0, incoherentNsPerRay = 0, shadowNsPerRay = 0;

  double medianMrays(const std::vector<Run>& runs) const {
    std::vector<double> v;
    for (const Run& r : runs) v.push_back(r.mrays());
    return median(v);
  }
  // The frame's rays traced alone at the kernel's traversal rates: camera rays at the camera
  // set's, the other extension rays at the incoherent set's, shadow rays at the shadow set's.
  double traversalOnlyOverFrame() const {
    std::vector<double> v;
    for (const Run& r : qlight) {
      double extension = double(r.rays - r.shadowRays - r.paths);
      double ms = (r.paths * cameraNsPerRay + extension * incoherentNsPerRay +
                   r.shadowRays * shadowNsPerRay) *
                  1e-6;
      v.push_back(ms / r.gpuMs);
    }
    return median(v);
  }
};

ImageMean meanOf(const std::vector<glm::vec3>& image, double varianceSum) {
  double sum = 0;
  for (const glm::vec3& c : image) sum += shared::luminance(c);
  return {sum / image.size(), std::sqrt(varianceSum) / image.size()};
}

Run renderQlight(const gpu::Context& ctx, const WorldScene& scene, const Options& o,
                 ImageMean* mean) {
  render::RenderSettings s;
  s.width = o.width;
  s.height = o.height;
  s.samplesPerFrame = kSamplesPerFrame;
  s.seed = kSeed;
  session::OfflineRender r = session::renderScene(ctx, scene.asset, s, o.spp, 0.0f);
  Run run;
  run.wallMs = r.stats.seconds * 1e3;
  run.rays = r.stats.counters.rays;
  run.shadowRays = r.stats.counters.shadowRays;
  run.paths = r.stats.counters.paths;
  for (const auto& [pass, ms] : r.stats.gpuMs) run.gpuMs += ms;
  if (mean) {
    std::vector<glm::vec3> image;
    for (size_t i = 0; i + 3 < r.image.rgba.size(); i += 4)
      image.push_back({r.image.rgba[i], r.image.rgba[i + 1], r.image.rgba[i + 2]});
    *mean = meanOf(image, 0.0);
  }
  return run;
}

Run renderEmbree(const EmbreePathTracer& tracer, const Options& o, ImageMean* mean) {
  PathTraceSettings s;
  s.width = o.width;
  s.height = o.height;
  s.spp = o.spp;
  s.seed = kSeed;
  s.threads = o.threads;
  PathTraceResult r = tracer.render(s);
  if (mean) *mean = meanOf(r.image, r.meanVarianceSum);
  return {r.wallMs, r.rays, r.shadowRays, r.paths, 0.0};
}

// ns per ray of qlight's traversal alone on one of the bench's ray sets (median of 5).
double traversalNsPerRay(const gpu::Context& ctx, QlightTracer& tracer, const RaySet& set) {
  DeviceRays rays(ctx, set);
  tracer.trace(rays);  // warm-up
  std::vector<double> ms;
  for (int i = 0; i < 5; ++i) ms.push_back(tracer.trace(rays));
  return median(ms) * 1e6 / double(set.rays.size());
}

SceneFigures runScene(const gpu::Context& ctx, const fs::path& path, const Options& o) {
  std::fprintf(stderr, "%s: %s: loading\n", kName, path.filename().c_str());
  WorldScene scene = loadWorldScene(path, float(o.width) / float(o.height));
  SceneFigures f;
  f.name = scene.name;
  f.triangles = scene.triangleCount;
  EmbreeTracer embree(scene, o.threads);
  EmbreePathTracer pathTracer(scene, embree.scene());
  {
    // bench_traversal_vs_embree's ray sets at its size (a dispatch of a few thousand rays
    // would time lavapipe's fixed costs), for the kernel's rate per ray.
    QlightTracer traversal(ctx, scene);
    RaySet camera = cameraRays(scene.camera, kTraversalWidth, kTraversalHeight, kSeed);
    std::vector<TraceHit> hits;
    embree.trace(camera, hits);
    f.cameraNsPerRay = traversalNsPerRay(ctx, traversal, camera);
    f.incoherentNsPerRay =
        traversalNsPerRay(ctx, traversal, incoherentRays(scene, camera, hits, kSeed));
    f.shadowNsPerRay = traversalNsPerRay(ctx, traversal, shadowRays(scene, camera, hits, kSeed));
  }
  std::fprintf(stderr, "%s: %s: %u renders a side at %ux%u, %u spp\n", kName, f.name.c_str(),
               o.reps, o.width, o.height, o.spp);
  renderQlight(ctx, scene, o, nullptr);  // warm-up: pipelines, page faults
  for (uint32_t i = 0; i < o.reps; ++i) {
    bool last = i + 1 == o.reps;
    f.qlight.push_back(renderQlight(ctx, scene, o, last ? &f.qlightMean : nullptr));
    f.embree.push_back(renderEmbree(pathTracer, o, last ? &f.embreeMean : nullptr));
  }
  return f;
}

json runJson(const Run& r) {
  return {{"wall_ms", r.wallMs},         {"gpu_ms", r.gpuMs}, {"rays", r.rays},
          {"shadow_rays", r.shadowRays}, {"paths", r.paths},  {"mrays_per_s", r.mrays()}};
}

}  // namespace

int main(int argc, char** argv) {
  Options o = parse(argc, argv);
  if (o.scenes.empty()) fail("no scene to run", 1);
  try {
    gpu::ContextOptions co = gpu::defaultContextOptions();
    co.quiet = true;
    gpu::Context ctx(co);
    std::fprintf(stderr, "%s: Vulkan device \"%s\", Embree %s on %u threads\n", kName,
                 ctx.deviceName().c_str(), embreeVersion().c_str(), o.threads);
    json scenes = json::array();
    bool agreed = true;
    for (const fs::path& p : o.scenes) {
      SceneFigures f = runScene(ctx, p, o);
      if (scenes.empty())
        std::printf(
            "| scene (triangles) | qlight frame Mrays/s | Embree path tracer Mrays/s | frame / "
            "Embree | frame / traversal alone | shadow rays a path: qlight / Embree | image mean: "
            "qlight / Embree |\n| --- | ---: | ---: | ---: | ---: | ---: | ---: |\n");
      double q = f.medianMrays(f.qlight), e = f.medianMrays(f.embree);
      double trav = f.traversalOnlyOverFrame();
      const Run &ql = f.qlight.back(), &em = f.embree.back();
      std::printf(
          "| %s (%llu) | %.2f | %.2f | %.2fx | %.2fx | %.3f / %.3f | %.4g / %.4g (±%.2g) |\n",
          f.name.c_str(), (unsigned long long)f.triangles, q, e, q / e, trav,
          double(ql.shadowRays) / ql.paths, double(em.shadowRays) / em.paths, f.qlightMean.mean,
          f.embreeMean.mean, f.embreeMean.standardError);
      std::fflush(stdout);
      // Both render one light transport, so their means agree within the noise; qlight's own
      // standard error is taken as Embree's (same estimator, same samples).
      double allowed = kMeanSigmas * std::sqrt(2.0) * f.embreeMean.standardError;
      if (!(std::abs(f.qlightMean.mean - f.embreeMean.mean) <= allowed)) {
        std::fprintf(stderr,
                     "%s: %s: the two images' means differ by more than %g standard errors\n",
                     kName, f.name.c_str(), kMeanSigmas);
        agreed = false;
      }
      json runs = {{"qlight", json::array()}, {"embree", json::array()}};
      for (const Run& r : f.qlight) runs["qlight"].push_back(runJson(r));
      for (const Run& r : f.embree) runs["embree"].push_back(runJson(r));
      scenes.push_back({{"scene", f.name},
                        {"triangles", f.triangles},
                        {"qlight_mrays_per_s", q},
                        {"embree_mrays_per_s", e},
                        {"frame_over_embree", q / e},
                        {"frame_over_traversal_only", trav},
                        {"traversal_ns_per_ray",
                         {{"camera", f.cameraNsPerRay},
                          {"incoherent", f.incoherentNsPerRay},
                          {"shadow", f.shadowNsPerRay}}},
                        {"image_mean_luminance",
                         {{"qlight", f.qlightMean.mean},
                          {"embree", f.embreeMean.mean},
                          {"embree_standard_error", f.embreeMean.standardError}}},
                        {"runs", runs}});
    }
    if (!o.out.empty()) {
      std::ofstream out(o.out);
      out << json{{"device", ctx.deviceName()},
                  {"embree", embreeVersion()},
                  {"threads", o.threads},
                  {"width", o.width},
                  {"height", o.height},
                  {"spp", o.spp},
                  {"reps", o.reps},
                  {"scenes", scenes}}
                 .dump(2)
          << "\n";
      if (!out) fail("cannot write " + o.out, 1);
    }
    if (!agreed) return 1;
  } catch (const std::exception& e) {
    fail(e.what(), 1);
  }
  return 0;
}
