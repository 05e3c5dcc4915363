#include "game/demo_command.h"

#include <GLFW/glfw3.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>

#include "engine/gpu/pass_recorder.h"
#include "engine/render/gpu_scene.h"
#include "engine/render/path_tracer.h"
#include "engine/guiding/q_guiding.h"
#include "engine/session/scene_world.h"
#include "engine/session/stats_json.h"
#include "engine/scene/gltf_loader.h"
#include "game/context_setup.h"
#include "game/demo_window.h"
#include "game/flythrough.h"

namespace qlight::game {
namespace {

namespace fs = std::filesystem;

// A scene name resolves against the working directory, then the shipped assets.
std::string resolveScene(const std::string& name) {
  if (fs::exists(name)) return name;
  fs::path shipped = fs::path(QLIGHT_ASSETS_DIR) / name;
  if (fs::exists(shipped)) return shipped.string();
  if (fs::exists(shipped.string() + ".gltf")) return shipped.string() + ".gltf";
  return name;  // the loader reports it missing, naming it
}

bool displayAvailable() {
  const char* d = std::getenv("DISPLAY");
  const char* w = std::getenv("WAYLAND_DISPLAY");
  return (d && *d) || (w && *w);
}

int runHeadless(const DemoArgs& a, const CommonOptions& common) {
  scene::SceneAsset asset = scene::loadGltf(resolveScene(a.scene));
  auto ctx = createContext(common, false);
  render::RenderSettings s = a.settings;
  session::SceneWorld world(asset, float(s.width) / float(s.height));
  render::GpuScene gpuScene(*ctx, asset);
  gpuScene.update(world.draw());
  render::PathTracer tracer(*ctx, s);
  gpu::GpuTimer timer(*ctx);
  Flythrough path{world.camera(), asset.bounds.radius(), a.moveSeconds};
  std::unique_ptr<guiding::QGuiding> guide;
  if (a.guiding.enabled) {
    guide = std::make_unique<guiding::QGuiding>(*ctx, a.guiding);
    guide->generatePoints(world.registry(), gpuScene);
  }

  fs::create_directories(a.outDir);
  nlohmann::json frames = nlohmann::json::array();
  render::RenderStats total;
  total.width = s.width;
  total.height = s.height;
  total.device = ctx->deviceName();
  auto start = std::chrono::steady_clock::now();
  for (uint32_t f = 0; f < a.frames; ++f) {
    float t = float(f) / a.fps;
    world.advance(t);
    if (world.moved()) {
      // Moving lights change the image: accumulation restarts (or fades, with
      // temporal blending), while the learned distributions persist and follow the lights.
      gpuScene.update(world.draw());
      if (s.temporalBlend > 0.0f) tracer.fadeAccumulation(s.temporalBlend);
      else tracer.resetAccumulation();
    }
    render::CameraView camera = path.at(t);
    auto frameStart = std::chrono::steady_clock::now();
    ctx->submitAndWait([&](VkCommandBuffer cmd) {
      timer.reset(cmd);
      gpu::PassRecorder rec(*ctx, cmd, &timer);
      tracer.recordFrame(rec, gpuScene, camera, guide ? guide->binder() : render::GuidingBinder{});
      if (guide) guide->recordLearning(rec);
      rec.finish();
    });
    if (guide) guide->afterFrame(world.registry());
    double frameSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - frameStart).count();
    render::FrameCounters c = tracer.collectCounters();
    auto gpuMs = timer.collect(*ctx);
    total.counters += c;
    for (auto& [name, ms] : gpuMs) total.gpuMs[name] += ms;
    ++total.frames;
    total.spp += s.samplesPerFrame;
    frames.push_back({{"frame", f},
                      {"time", t},
                      {"seconds", frameSeconds},
                      {"accumulated_spp", tracer.accumulatedSamples()},
                      {"rays", c.rays},
                      {"emitter_hit_share", double(c.emitterHits) / double(std::max<uint64_t>(c.paths, 1))},
                      {"mean_path_length", double(c.pathVertices) / double(std::max<uint64_t>(c.paths, 1))},
                      {"gpu_ms", gpuMs}});
    bool last = f + 1 == a.frames;
    if (last || (a.saveEvery > 0 && f % a.saveEvery == 0)) {
      char name[64];
      std::snprintf(name, sizeof(name), "frame_%04u.png", f);
      render::writeImage(fs::path(a.outDir) / name, tracer.readImage(), s.exposure, s.tonemap);
    }
  }
  total.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  total.lights = gpuScene.lightCount();
  total.fallbackSky = gpuScene.usesFallbackSky();
  total.guided = bool(guide);
  if (guide) total.guidingStats = guide->stats();
  nlohmann::json stats = render::statsToJson(total);
  stats["scene"] = resolveScene(a.scene);
  stats["mode"] = "headless";
  stats["frames_detail"] = frames;
  render::writeJson(fs::path(a.outDir) / "stats.json", stats);
  render::writeImage(fs::path(a.outDir) / "final.png", tracer.readImage(), s.exposure, s.tonemap);
  std::printf("qlight demo: %u frames of %s at %ux%u in %.2f s (%.1f ms/frame, %.2f Mrays/s); "
              "images and stats.json in %s\n",
              a.frames, a.scene.c_str(), s.width, s.height, total.seconds,
              1e3 * total.seconds / std::max(1u, a.frames),
              stats["rays_per_second"].get<double>() * 1e-6, a.outDir.c_str());
  return finishContext(*ctx);
}

}  // namespace

std::function<int()> addDemoCommand(CLI::App& app, const CommonOptions& common) {
  auto args = std::make_shared<DemoArgs>();
  CLI::App* cmd = app.add_subcommand("demo", "the flythrough (window, or headless frames)");
  cmd->add_option("--scene", args->scene, "glTF file or shipped scene name")->capture_default_str();
  cmd->add_option("--frames", args->frames, "headless: frames to render")->check(CLI::Range(1, 100000))->capture_default_str();
  cmd->add_option("--fps", args->fps, "headless: frames per second of scene time")->check(CLI::Range(1.0, 1000.0));
  cmd->add_option("--move-seconds", args->moveSeconds, "headless: seconds the camera moves before it stops")
      ->check(CLI::Range(0.0, 1e6));
  cmd->add_option("--save-every", args->saveEvery, "headless: write every Nth frame (0: last only)");
  cmd->add_option("--out", args->outDir, "headless: output folder")->capture_default_str();
  cmd->add_option("--spp-per-frame", args->settings.samplesPerFrame, "samples per pixel per frame")
      ->check(CLI::Range(1, 4096));
  cmd->add_flag("--headless", args->headless, "render frames to files even with a display");
  cmd->add_option("--exit-after-frames", args->exitAfterFrames, "window: close after this many frames (0: never)");
  cmd->add_option("--screenshot-at-exit", args->screenshotAtExit, "window: write the render as PNG on closing");
  args->settings.temporalBlend = 0.7f;  // the demo keeps a fading history of animated frames
  addRenderOptions(*cmd, args->settings);
  addGuidingOptions(*cmd, args->guiding, args->guidingCli);
  return [cmd, args, &common]() -> int {
    if (!cmd->parsed()) return -1;
    finishGuidingOptions(args->guidingCli, args->guiding, args->settings);
    if (!args->headless && displayAvailable() && glfwInit()) {
      args->scene = resolveScene(args->scene);
      return runWindowed(*args, common);
    }
    if (!args->headless)
      std::fprintf(stderr, "qlight demo: no display, rendering headless to %s\n", args->outDir.c_str());
    return runHeadless(*args, common);
  };
}

}  // namespace qlight::game
