// Rays per second on the GPU (lavapipe or a real one), from GPU timestamps:
// traversal alone (coherent camera rays, incoherent closest hit, shadow rays)
// and whole path tracing frames, unguided and guided, side by side.
#include <benchmark/benchmark.h>

#include <memory>

#include "engine/gltf/gltf_loader.h"
#include "engine/gpu/gpu_timer.h"
#include "engine/gpu/pass_recorder.h"
#include "engine/session/offline_render.h"
#include "engine/session/scene_world.h"
#include "shaders/shared/trace_bench.h"

namespace {

using namespace qlight;

struct Fixture {
  std::unique_ptr<gpu::Context> ctx;
  std::map<std::string, scene::SceneAsset> scenes;
  Fixture() {
    gpu::ContextOptions o = gpu::defaultContextOptions();
    o.quiet = true;
    ctx = std::make_unique<gpu::Context>(o);
  }
  const scene::SceneAsset& scene(const std::string& name) {
    auto it = scenes.find(name);
    if (it == scenes.end())
      it = scenes.emplace(name, gltf::loadGltf(std::string(QLIGHT_SOURCE_DIR) + "/assets/" + name))
               .first;
    return it->second;
  }
};

Fixture& fixture() {
  static Fixture f;
  return f;
}

const char* kScenes[] = {"cornell_box.gltf", "door_ajar.gltf"};

// mode 0: camera rays, 1: incoherent closest hit, 2: incoherent shadow rays.
void BM_Traversal(benchmark::State& state) {
  Fixture& f = fixture();
  const scene::SceneAsset& asset = f.scene(kScenes[state.range(0)]);
  const uint32_t mode = uint32_t(state.range(1));
  const uint32_t width = 640, height = 360, rays = width * height;
  session::SceneWorld world(asset, float(width) / height);
  render::GpuScene scene(*f.ctx, asset);
  scene.update(world.draw());
  // Specialized like the path passes: no alpha-test or texture code in opaque scenes.
  gpu::ComputePipeline pipeline(*f.ctx, "trace_bench", scene.specializationFeatures());
  gpu::Buffer uniforms(*f.ctx, sizeof(shared::FrameUniforms), "uniforms");
  gpu::Buffer stats(*f.ctx, 64, "stats");
  shared::FrameUniforms u{};
  render::CameraView cam = world.camera();
  u.camera.position = cam.position;
  u.camera.forward = glm::normalize(cam.forward);
  u.camera.right = glm::normalize(glm::cross(u.camera.forward, cam.up));
  u.camera.up = glm::cross(u.camera.right, u.camera.forward);
  u.camera.tanHalfFovY = std::tan(0.5f * cam.yfov);
  u.camera.aspect = float(width) / height;
  u.resolution = glm::uvec2(width, height);
  u.sceneCenter = scene.boundsCenter();
  u.sceneRadius = scene.boundsRadius();
  u.seed = 1;
  uniforms.upload(*f.ctx, &u, sizeof(u));
  gpu::GpuTimer timer(*f.ctx);
  shared::TraceBenchPush push{rays, mode, 0, 0};
  for (auto _ : state) {
    f.ctx->submitAndWait([&](VkCommandBuffer cmd) {
      timer.reset(cmd);
      gpu::PassRecorder rec(*f.ctx, cmd, &timer);
      auto pass = rec.pass("trace", pipeline);
      scene.bind(pass);
      pass.read(QL_BIND_FRAME, uniforms)
          .write(QL_BIND_STATS, stats)
          .push(push)
          .dispatchThreads(rays);
      rec.finish();
    });
    state.SetIterationTime(timer.collect(*f.ctx)["trace"] * 1e-3);
  }
  state.counters["Mrays/s"] =
      benchmark::Counter(double(rays) * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
  state.SetLabel(std::string(kScenes[state.range(0)]) + (mode == 0   ? " camera"
                                                         : mode == 1 ? " incoherent"
                                                                     : " shadow"));
}
BENCHMARK(BM_Traversal)
    ->ArgsProduct({{0, 1}, {0, 1, 2}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->MinTime(1.0);

// Whole frames at 320x180, 4 spp each: rays/s and the learning passes' share.
void BM_PathTrace(benchmark::State& state) {
  Fixture& f = fixture();
  const scene::SceneAsset& asset = f.scene(kScenes[state.range(0)]);
  const bool guided = state.range(1) != 0;
  render::RenderSettings s;
  s.samplesPerFrame = 4;
  guiding::GuidingSettings g;
  g.enabled = guided;
  double gpuMs = 0, learnMs = 0;
  uint64_t rays = 0;
  for (auto _ : state) {
    auto r = session::renderScene(*f.ctx, asset, s, 16, 0.0f, g);
    double frameMs = 0;
    for (auto& [name, ms] : r.stats.gpuMs) {
      frameMs += ms;
      if (name.rfind("guiding", 0) == 0 || name.rfind("prefix_sum", 0) == 0) learnMs += ms;
    }
    gpuMs += frameMs;
    rays += r.stats.counters.rays;
    state.SetIterationTime(frameMs * 1e-3);
  }
  state.counters["Mrays/s"] = double(rays) / (gpuMs * 1e-3) * 1e-6;
  state.counters["learning share"] = learnMs / gpuMs;
  state.SetLabel(std::string(kScenes[state.range(0)]) + (guided ? " guided" : " unguided"));
}
BENCHMARK(BM_PathTrace)
    ->ArgsProduct({{0, 1}, {0, 1}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(2);

}  // namespace
