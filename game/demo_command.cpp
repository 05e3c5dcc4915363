#include "game/demo_command.h"

#include <GLFW/glfw3.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>

#include "engine/gltf/gltf_loader.h"
#include "engine/session/renderer.h"
#include "engine/session/stats_json.h"
#include "engine/ui/display_filter.h"
#include "game/cli_options.h"
#include "game/context_setup.h"
#include "game/demo_timeline.h"
#include "game/demo_window.h"
#include "game/environment_choice.h"
#include "game/frame_video.h"
#include "game/process_memory.h"
#include "game/progress_bar.h"
#include "game/shipped_scenes.h"

namespace qlight::game {
namespace {

namespace fs = std::filesystem;

bool displayAvailable() {
  const char* d = std::getenv("DISPLAY");
  const char* w = std::getenv("WAYLAND_DISPLAY");
  return (d && *d) || (w && *w);
}

// The MP4 needs every frame; ffmpeg is optional, so without it this only says why not.
void writeVideo(const DemoArgs& a, const DemoTimeline& timeline) {
  if (!timeline.everyFrameWritten()) return;
  const fs::path mp4 = fs::path(a.outDir) / "flythrough.mp4";
  const VideoResult video = encodeFrames(a.outDir, timeline.frames(), a.fps, mp4);
  if (video.written)
    std::printf("qlight demo: %s (%u frames at %g fps)\n", mp4.c_str(), timeline.frames(), a.fps);
  else
    std::printf("qlight demo: MP4 skipped: %s\n", video.why.c_str());
}

int runHeadless(const DemoArgs& a, const CommonOptions& common) {
  scene::SceneAsset asset = gltf::loadGltf(resolveScene(a.scene));
  attachEnvironment(asset, a.environment);
  auto ctx = createContext(common, false);
  const render::RenderSettings& s = a.settings;
  session::Renderer renderer(*ctx, asset, s, a.guiding);
  reportSceneLighting(renderer.scene().usesFallbackSky(), renderer.scene().glowMapsOnly(),
                      renderer.scene().hasEnvironment(), asset, a.scene);
  const DemoTimeline timeline(a, renderer.world().camera(), asset.bounds.radius());
  const uint32_t frameCount = timeline.frames();

  // The PNG frames through the window's display filter, as the window shows them (both parts on
  // by default; --denoise off --reuse-history off writes the traced image): the accumulation,
  // stats.json and the timings stay unfiltered.
  std::optional<ui::DisplayFilter> filter;
  ui::DisplayFilterSettings filterSettings;
  filterSettings.reuseHistory = a.reuseHistory;
  filterSettings.denoise = a.denoise;
  filterSettings.maxLuminance = 4.0f / std::max(s.exposure, 1e-6f);
  if (filterSettings.active()) filter.emplace(*ctx);
  auto shownImage = [&]() { return filter ? filter->readOutput() : renderer.tracer().readImage(); };

  fs::create_directories(a.outDir);
  nlohmann::json frames = nlohmann::json::array();
  session::RenderStats total = renderer.newStats();
  ProgressBar progress(frameCount, "qlight demo");
  auto start = std::chrono::steady_clock::now();
  for (uint32_t f = 0; f < frameCount; ++f) {
    float t = timeline.time(f);
    auto frameStart = std::chrono::steady_clock::now();
    session::FrameResult r = renderer.renderFrame(t, timeline.camera(t));
    double frameSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - frameStart).count();
    total.add(r);
    frames.push_back({{"frame", f},
                      {"time", t},
                      {"seconds", frameSeconds},
                      {"accumulated_spp", renderer.tracer().accumulatedSamples()},
                      {"rays", r.counters.rays},
                      {"emitter_hit_share", r.emitterHitShare()},
                      {"mean_path_length", r.meanPathLength()},
                      {"invalid_samples", r.counters.invalidSamples},
                      {"resident_mib", residentMegabytes()},
                      {"device_allocations", ctx->memoryInUse().allocations},
                      {"device_mib", double(ctx->memoryInUse().bytes) / (1024.0 * 1024.0)},
                      {"gpu_ms", r.gpuMs}});
    if (filter)
      ctx->submitAndWait([&](VkCommandBuffer cmd) {
        gpu::PassRecorder rec(*ctx, cmd);
        filter->record(rec, renderer.scene(), renderer.tracer().accumulation(),
                       renderer.tracer().keptOfPrevious(),
                       renderer.world().registry().resource<session::FrameView>().camera,
                       filterSettings);
        rec.finish();
      });
    if (timeline.written(f)) {
      char name[64];
      std::snprintf(name, sizeof(name), "frame_%04u.png", f);
      image::writeImage(fs::path(a.outDir) / name, shownImage(), s.exposure, s.tonemap);
    }
    progress.update(f + 1, "frame " + std::to_string(f + 1) + " of " + std::to_string(frameCount));
  }
  progress.finish();
  total.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (renderer.guide()) total.guidingStats = renderer.guide()->stats();
  nlohmann::json stats = session::statsToJson(total);
  stats["scene"] = resolveScene(a.scene);
  stats["mode"] = "headless";
  stats["camera"] = timeline.name();
  if (!a.cameraPathFile.empty()) stats["camera_path"] = a.cameraPathFile;
  stats["frames_detail"] = frames;
  if (const guiding::QGuide* guide = renderer.guide(); guide && a.guiding.enabled) {
    const guiding::LearnedTables::ValueRange q = guide->qRange();
    stats["q_min"] = q.min;
    stats["q_max"] = q.max;
    stats["q_non_finite"] = q.nonFinite;
  }
  session::writeJson(fs::path(a.outDir) / "stats.json", stats);
  image::writeImage(fs::path(a.outDir) / "final.png", shownImage(), s.exposure, s.tonemap);
  std::printf(
      "qlight demo: %u frames of %s at %ux%u in %.2f s (%.1f ms/frame, %.2f Mrays/s); "
      "images and stats.json in %s\n",
      frameCount, a.scene.c_str(), s.width, s.height, total.seconds,
      1e3 * total.seconds / std::max(1u, frameCount), stats["rays_per_second"].get<double>() * 1e-6,
      a.outDir.c_str());
  writeVideo(a, timeline);
  return finishContext(*ctx);
}

}  // namespace

std::function<int()> addDemoCommand(CLI::App& app, const CommonOptions& common) {
  auto args = std::make_shared<DemoArgs>();
  CLI::App* cmd = app.add_subcommand("demo", "the flythrough (window, or headless frames)");
  cmd->add_option("--scene", args->scene, "glTF file or shipped scene name")->capture_default_str();
  CLI::Option* frames = cmd->add_option("--frames", args->frames, "headless: frames to render")
                            ->check(CLI::Range(1u, kMaxDemoFrames))
                            ->capture_default_str();
  cmd->add_option("--fps", args->fps, "headless: frames per second of scene time")
      ->check(finiteRange(1.0, 1000.0));
  CLI::Option* moveSeconds = cmd->add_option("--move-seconds", args->moveSeconds,
                                             "headless: seconds the camera moves before it stops")
                                 ->check(finiteRange(0.0, 1e6));
  CLI::Option* saveEvery = cmd->add_option("--save-every", args->saveEvery,
                                           "headless: write every Nth frame (0: last only)");
  CLI::Option* camera =
      cmd->add_option("--camera", args->camera,
                      "headless: sway (around the scene's camera) or gltf (the scene's own, "
                      "possibly animated camera)")
          ->check(CLI::IsMember({"sway", "gltf"}))
          ->capture_default_str();
  cmd->add_option("--camera-path", args->cameraPathFile,
                  "play this camera path (headless: all of it at --fps, every frame written; "
                  "window: then the free camera takes over)")
      ->excludes(frames, moveSeconds, camera, saveEvery);
  cmd->add_option("--record-path", args->recordPath,
                  "window: F9 records the camera into this file (default OUT/camera_path.json)");
  cmd->add_option("--out", args->outDir, "headless: output folder")->capture_default_str();
  cmd->add_option("--spp-per-frame", args->settings.samplesPerFrame, "samples per pixel per frame")
      ->check(wholeRange(ranges::kSamplesPerFrame));
  cmd->add_flag("--headless", args->headless, "render frames to files even with a display");
  cmd->add_option("--exit-after-frames", args->exitAfterFrames,
                  "window: close after this many frames (0: never)");
  cmd->add_option("--screenshot-at-exit", args->screenshotAtExit,
                  "window: write the render as PNG on closing");
  cmd->add_option("--render-scale", args->window.renderScale,
                  "window: render size as a share of the window's (a still camera's)")
      ->check(finiteRange(ranges::kRenderScale))
      ->capture_default_str();
  cmd->add_option("--target-frame-ms", args->window.targetFrameMs,
                  "window: frame time held by a smaller render while the camera moves (0: off)")
      ->check(finiteRange(ranges::kTargetFrameMs))
      ->capture_default_str();
  cmd->add_option("--vsync", args->window.vsync,
                  "window: on waits for vertical blank (FIFO); off presents every frame")
      ->transform(CLI::CheckedTransformer(onOffWords(), CLI::ignore_case));
  cmd->add_flag("--show-cache-points", args->showCachePoints,
                "window: draw the cache points over the image from the start (panel: Guiding)");
  cmd->add_option("--reuse-history", args->reuseHistory,
                  "reproject the last frame while the camera moves, on|off (display only: "
                  "the window and the headless PNG frames)")
      ->transform(CLI::CheckedTransformer(onOffWords(), CLI::ignore_case));
  cmd->add_option("--denoise", args->denoise,
                  "edge-aware a-trous denoiser, on|off (display only: the window and the "
                  "headless PNG frames)")
      ->transform(CLI::CheckedTransformer(onOffWords(), CLI::ignore_case));
  cmd->add_option("--inspect-at", args->inspectAt,
                  "window: show the learned Q at this window pixel X Y instead of the cursor's")
      ->expected(2)
      ->check(finiteRange(0.0, 1e5));
  cmd->add_option("--scripted-move-frames", args->scriptedMoveFrames,
                  "window: fly forward and back (8 frames each way, turning) for the first N "
                  "frames, then stay still")
      ->check(CLI::Range(0, 1000000));
  auto script = std::make_shared<std::vector<std::string>>();
  cmd->add_option("--script", *script,
                  "window: FRAME:resize=WxH, FRAME:vsync=on|off, FRAME:load=FILE or "
                  "FRAME:save=FILE (repeatable; tests)");
  args->settings.temporalBlend = 0.7f;  // the demo keeps a fading history of animated frames
  // The demo's lights move: what was learned fades (the tracking study: docs/tracking.md).
  args->guiding.halfLifeFrames = kDemoHalfLifeFrames;
  args->guiding.forgetOnLightMove = kDemoForgetOnLightMove;
  addRenderOptions(*cmd, args->settings);
  addGuidingOptions(*cmd, args->guiding, args->guidingCli);
  addEnvironmentOptions(*cmd, args->environment, args->skyText);
  addSettingsOption(*cmd, args->settingsFile);
  return [cmd, args, script, &common]() -> int {
    if (!cmd->parsed()) return -1;
    Settings file{args->settings, args->guiding, args->window, args->environment};
    applySettingsFile(*cmd, args->settingsFile, file);
    args->settings = file.render;
    args->guiding = file.guiding;
    args->window = file.window;
    args->environment = file.environment;
    finishEnvironmentOptions(*cmd, args->skyText, args->environment);
    finishGuidingOptions(args->guidingCli, args->guiding, args->settings);
    for (const std::string& step : *script) args->script.push_back(parseScriptStep(step));
    // A bad path file is one error line before any device or window starts.
    if (!args->cameraPathFile.empty()) {
      args->cameraPath = loadCameraPath(args->cameraPathFile);
      args->frames = framesAlong(args->cameraPath, args->fps, args->cameraPathFile);
    }
    if (args->recordPath.empty())
      args->recordPath = (fs::path(args->outDir) / "camera_path.json").string();
    if (!args->headless && displayAvailable() && glfwInit()) {
      args->scene = resolveScene(args->scene);
      return runWindowed(*args, common);
    }
    if (!args->headless)
      std::fprintf(stderr, "qlight demo: no display, rendering headless to %s\n",
                   args->outDir.c_str());
    return runHeadless(*args, common);
  };
}

}  // namespace qlight::game
