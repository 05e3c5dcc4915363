// bench_traversal_vs_embree: the same rays through qlight's GPU traversal and
// through Embree's single-ray CPU traversal on the same cores, per scene and
// ray kind; checks that both find the same hits and reports the speed ratio.
// On lavapipe this is qlight's traversal against the practical limit of the
// machine. Usage: see kUsage.
#include <sys/resource.h>
#include <time.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "bench/traversal_vs_embree/embree_tracer.h"
#include "bench/traversal_vs_embree/hit_compare.h"
#include "bench/traversal_vs_embree/qlight_tracer.h"
#include "bench/traversal_vs_embree/ray_sets.h"
#include "bench/traversal_vs_embree/report.h"
#include "bench/traversal_vs_embree/world_scene.h"
#include "engine/gpu/context.h"

namespace {

using namespace qlight;
using namespace qlight::bench;
namespace fs = std::filesystem;

constexpr const char* kName = "bench_traversal_vs_embree";
constexpr const char* kUsage =
    "usage: bench_traversal_vs_embree [SCENE.gltf ...] [--out FILE.json] [--quick] [--reps N]\n"
    "                                 [--threads N] [--two-level]\n"
    "  SCENE      a glTF path, or the file name of a default scene or of one in assets/\n"
    "             (default: every shipped scene and the 1M-triangle\n"
    "             MetalRoughSpheresNoTextures sample)\n"
    "  --out      also write every figure as JSON\n"
    "  --quick    320x180 rays and 3 repetitions (default 640x360 and 9)\n"
    "  --reps N   repetitions per ray set (median reported)\n"
    "  --threads  Embree's threads (default: LP_NUM_THREADS, else the core count, as lavapipe)\n"
    "  --two-level  qlight keeps every instance in its top level (no merged BLAS of the\n"
    "             fixed instances), as it traced before 2026-12-04\n";

const char* kDefaultScenes[] = {
    "assets/cornell_box.gltf",
    "assets/door_ajar.gltf",
    "assets/many_lights.gltf",
    "assets/animated_light.gltf",
    "tests/data/gltf-samples/features/MetalRoughSpheresNoTextures/glTF/"
    "MetalRoughSpheresNoTextures.gltf",
};

constexpr uint32_t kSeed = 20240611;
constexpr float kRelativeTolerance = 1e-4f;
constexpr float kMaxMismatchFraction = 1e-4f;

struct Options {
  std::vector<fs::path> scenes;
  std::string out;
  bool quick = false;
  uint32_t reps = 0;  // 0: the mode's default
  unsigned threads = 0;
  bool twoLevel = false;
};

[[noreturn]] void fail(const std::string& message, int code = 2) {
  std::fprintf(stderr, "%s: %s\n", kName, message.c_str());
  std::exit(code);
}

uint32_t positive(const std::string& flag, const char* value) {
  char* end = nullptr;
  long v = std::strtol(value, &end, 10);
  if (!*value || *end || v < 1 || v > 100000)
    fail(flag + " wants a positive whole number, not '" + value + "'");
  return uint32_t(v);
}

// A scene argument is a path, or the file name of a default scene or of a file in assets/.
fs::path resolveScene(const std::string& arg) {
  fs::path p(arg);
  if (fs::is_regular_file(p)) return p;
  const fs::path root(QLIGHT_SOURCE_DIR);
  for (const char* s : kDefaultScenes)
    if (fs::path(s) == p || fs::path(s).filename() == p) return root / s;
  if (fs::is_regular_file(root / "assets" / p)) return root / "assets" / p;
  fail("no scene file '" + arg + "' (neither a path nor a file in assets/)");
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    auto value = [&]() -> const char* {
      if (i + 1 >= argc) fail(a + " needs a value");
      return argv[++i];
    };
    if (a == "--help" || a == "-h") {
      std::fputs(kUsage, stdout);
      std::exit(0);
    } else if (a == "--out") {
      o.out = value();
    } else if (a == "--quick") {
      o.quick = true;
    } else if (a == "--reps") {
      o.reps = positive(a, value());
    } else if (a == "--two-level") {
      o.twoLevel = true;
    } else if (a == "--threads") {
      o.threads = positive(a, value());
    } else if (a.rfind("-", 0) == 0) {
      fail("unknown option " + a + " (see --help)");
    } else {
      o.scenes.push_back(resolveScene(a));
    }
  }
  if (o.scenes.empty())
    for (const char* s : kDefaultScenes) o.scenes.push_back(resolveScene(s));
  if (o.reps == 0) o.reps = o.quick ? 3 : 9;
  if (o.threads == 0) {
    const char* lp = std::getenv("LP_NUM_THREADS");
    o.threads = lp && std::atoi(lp) > 0 ? unsigned(std::atoi(lp))
                                        : std::max(1u, std::thread::hardware_concurrency());
  }
  return o;
}

std::string cpuModel() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown";
}

void loadAverage(double (&out)[3]) {
  if (getloadavg(out, 3) != 3) out[0] = out[1] = out[2] = -1;
}

// CPU time of the whole process: every thread lavapipe or Embree traces on.
double processCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

// Runs `trace` (which returns its own milliseconds) and appends those and the CPU time it took.
template <class F>
void timed(std::vector<double>& ms, std::vector<double>& cpuMs, F&& trace) {
  double cpu = processCpuMs();
  ms.push_back(trace());
  cpuMs.push_back(processCpuMs() - cpu);
}

// One ray set, qlight and Embree alternating per repetition so that drift of
// the shared machine's speed hits both sides alike.
SetResult measure(const gpu::Context& ctx, QlightTracer& qlight, const EmbreeTracer& embree,
                  const WorldScene& scene, const RaySet& set, const Options& o) {
  SetResult r;
  r.threads = o.threads;
  r.kind = set.kind;
  r.anyHit = set.anyHit;
  r.rays = uint32_t(set.rays.size());
  DeviceRays device(ctx, set);
  std::vector<TraceHit> embreeHits, packetHits;
  qlight.trace(device);  // warm-up: first-dispatch costs, caches, page faults
  embree.trace(set, embreeHits);
  embree.tracePackets8(set, packetHits);
  for (uint32_t i = 0; i < o.reps; ++i) {
    timed(r.qlightMs, r.qlightCpuMs, [&] { return qlight.trace(device); });
    timed(r.embreeMs, r.embreeCpuMs, [&] { return embree.trace(set, embreeHits); });
    r.embreePacketMs.push_back(embree.tracePackets8(set, packetHits));
  }
  std::vector<TraceHit> qlightHits = device.readHits(ctx);
  r.agreement = compareHits(qlightHits, embreeHits, set.anyHit, scene.size(), kRelativeTolerance);
  for (uint32_t i : r.agreement.examples)
    r.examples.push_back({i, set.rays[i], qlightHits[i], embreeHits[i]});
  // The packet figure is only worth quoting if the packets find what single rays do.
  r.packetMismatches =
      compareHits(packetHits, embreeHits, set.anyHit, scene.size(), kRelativeTolerance)
          .mismatches();
  return r;
}

SceneResult runScene(const gpu::Context& ctx, const fs::path& path, const Options& o,
                     uint32_t width, uint32_t height) {
  std::fprintf(stderr, "%s: %s: loading\n", kName, path.filename().c_str());
  WorldScene scene = loadWorldScene(path, float(width) / float(height));
  if (o.twoLevel)
    for (render::MeshDraw& d : scene.draws) d.fixed = false;
  SceneResult r;
  r.name = scene.name;
  r.path = fs::relative(path, QLIGHT_SOURCE_DIR).string();
  r.triangles = scene.triangleCount;
  r.meshTriangles = scene.meshTriangleCount;
  r.instances = uint32_t(scene.instances.size());
  r.emitters = uint32_t(scene.emitters.size());
  r.size = scene.size();

  std::fprintf(stderr, "%s: %s: %llu triangles, building both BVHs\n", kName, r.name.c_str(),
               (unsigned long long)r.triangles);
  QlightTracer qlight(ctx, scene);
  r.qlightBlasMs = qlight.blasBuildMs();
  r.qlightTlasMs = qlight.tlasBuildMs();
  r.qlightBvhBytes = qlight.bvhBytes();
  r.qlightNodes = qlight.nodeCount();
  EmbreeTracer embree(scene, o.threads);
  r.embreeGeometryMs = embree.geometryMs();
  r.embreeBuildMs = embree.buildMs();
  r.embreeBytes = embree.memoryBytes();
  r.embreePeakBytes = embree.peakMemoryBytes();

  // The secondary sets start where the camera rays hit (Embree finds those
  // hits; qlight's agree, as the camera set's check shows).
  RaySet camera = cameraRays(scene.camera, width, height, kSeed);
  std::vector<TraceHit> cameraHits;
  embree.trace(camera, cameraHits);
  RaySet incoherent = incoherentRays(scene, camera, cameraHits, kSeed);
  RaySet shadow = shadowRays(scene, camera, cameraHits, kSeed);
  for (const RaySet* set : {&camera, &incoherent, &shadow}) {
    std::fprintf(stderr, "%s: %s: tracing %s rays\n", kName, r.name.c_str(), set->kind.c_str());
    r.sets.push_back(measure(ctx, qlight, embree, scene, *set, o));
  }
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  Options o = parse(argc, argv);
  std::ofstream jsonFile;
  if (!o.out.empty()) {  // opened now, so a bad path fails before minutes of work
    jsonFile.open(o.out);
    if (!jsonFile) fail("cannot write " + o.out);
  }
  const uint32_t width = o.quick ? 320 : 640, height = o.quick ? 180 : 360;
  auto start = std::chrono::steady_clock::now();
  RunInfo info;
  loadAverage(info.loadBefore);
  try {
    gpu::ContextOptions co = gpu::defaultContextOptions();
    co.quiet = true;
    gpu::Context ctx(co);
    info.cpu = cpuModel();
    info.vulkanDevice = ctx.deviceName();
    info.embreeVersion = embreeVersion();
    info.threads = o.threads;
    info.width = width;
    info.height = height;
    info.reps = o.reps;
    info.seed = kSeed;
    info.quick = o.quick;
    info.validation = ctx.validationEnabled();
    info.relativeTolerance = kRelativeTolerance;
    info.maxMismatchFraction = kMaxMismatchFraction;
    std::fprintf(stderr,
                 "%s: Vulkan device \"%s\"%s, Embree %s on %u threads, %ux%u rays, %u reps\n",
                 kName, info.vulkanDevice.c_str(), info.validation ? " (validation on)" : "",
                 info.embreeVersion.c_str(), o.threads, width, height, o.reps);

    std::vector<SceneResult> results;
    for (const fs::path& p : o.scenes) results.push_back(runScene(ctx, p, o, width, height));

    bool agreed = true;
    for (const SceneResult& sc : results)
      for (const SetResult& s : sc.sets)
        if (s.agreement.mismatchFraction() > kMaxMismatchFraction) {
          agreed = false;
          std::fprintf(
              stderr, "%s: %s %s rays: %llu of %u disagree (%llu hit/miss, %llu distance)\n", kName,
              sc.name.c_str(), s.kind.c_str(), (unsigned long long)s.agreement.mismatches(), s.rays,
              (unsigned long long)s.agreement.hitMissDiffer,
              (unsigned long long)s.agreement.distanceDiffer);
        }
    // With QLIGHT_VALIDATION=1 the Vulkan side is checked too (any message fails).
    bool clean = !ctx.validationEnabled() || ctx.validationMessageCount() == 0;
    for (const std::string& m : ctx.validationMessages()) std::fprintf(stderr, "%s\n", m.c_str());
    bool passed = agreed && clean;
    loadAverage(info.loadAfter);
    info.wallSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    info.peakRssBytes = int64_t(usage.ru_maxrss) * 1024;

    printTable(std::cout, results);
    std::printf("\nload average before %.2f, after %.2f; %.1f s\n", info.loadBefore[0],
                info.loadAfter[0], info.wallSeconds);
    if (jsonFile.is_open()) {
      jsonFile << toJson(info, results, passed).dump(2) << "\n";
      if (!jsonFile.flush()) fail("cannot write " + o.out, 1);
    }
    if (!agreed)
      std::fprintf(stderr, "%s: FAILED: more than %g of the rays disagree\n", kName,
                   double(kMaxMismatchFraction));
    if (!clean) std::fprintf(stderr, "%s: FAILED: Vulkan validation messages\n", kName);
    if (!passed) return 1;
  } catch (const std::exception& e) {
    if (jsonFile.is_open()) {  // no half-measured file left behind
      jsonFile.close();
      std::error_code ignored;
      fs::remove(o.out, ignored);
    }
    fail(e.what(), 1);
  }
  return 0;
}
