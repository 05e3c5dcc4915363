#include "game/render_command.h"

#include <chrono>
#include <cstdio>
#include <memory>

#include "engine/gltf/gltf_loader.h"
#include "engine/gpu/context.h"
#include "engine/session/offline_render.h"
#include "engine/session/stats_json.h"
#include "game/cli_options.h"
#include "game/context_setup.h"
#include "game/environment_choice.h"
#include "game/progress_bar.h"

namespace qlight::game {
namespace {

struct RenderArgs {
  std::string scene;
  std::string out;
  std::string statsJson;
  std::string settingsFile;
  uint32_t spp = 64;
  float time = 0.0f;
  render::RenderSettings settings;  // samplesPerFrame: --batch
  guiding::GuidingSettings guiding;
  GuidingCli guidingCli;
  EnvironmentSettings environment;
  std::string skyText;  // --sky
};

int runRender(RenderArgs a, const CommonOptions& common) {
  image::checkImageExtension(a.out);
  finishGuidingOptions(a.guidingCli, a.guiding, a.settings);
  const auto loadStart = std::chrono::steady_clock::now();
  scene::SceneAsset asset = gltf::loadGltf(a.scene);
  attachEnvironment(asset, a.environment);
  const double loadSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - loadStart).count();
  auto ctx = createContext(common, /*windowed=*/false);
  render::RenderSettings s = a.settings;
  s.samplesPerFrame = std::min(s.samplesPerFrame, a.spp);
  ProgressBar progress(a.spp, "qlight render");
  session::OfflineRender result =
      session::renderScene(*ctx, asset, s, a.spp, a.time, a.guiding, [&](uint32_t done) {
        progress.update(done, std::to_string(done) + " of " + std::to_string(a.spp) + " spp");
      });
  progress.finish();
  reportSceneLighting(result.stats.fallbackSky, result.stats.glowMapsOnly,
                      result.stats.environmentLight, asset, a.scene);
  image::writeImage(a.out, result.image, s.exposure, s.tonemap);
  nlohmann::json stats = session::statsToJson(result.stats);
  stats["scene"] = a.scene;
  stats["load_seconds"] = loadSeconds;
  stats["time"] = a.time;
  stats["max_depth"] = s.maxDepth;
  stats["seed"] = s.seed;
  stats["estimator"] = wordOf(estimatorWords(), s.estimator);
  stats["russian_roulette"] = s.russianRoulette;
  if (!a.environment.file.empty()) stats["environment_map"] = a.environment.file;
  if (a.guiding.enabled) {
    stats["strata"] = std::to_string(a.guiding.rows) + "x" + std::to_string(a.guiding.cols);
    stats["alpha_min"] = a.guiding.alphaMin;
    stats["alpha_max"] = a.guiding.alphaMax;
    stats["light_learning"] = a.guiding.lightLearning;
  }
  if (!a.statsJson.empty()) session::writeJson(a.statsJson, stats);
  std::printf("qlight: %s -> %s: %ux%u, %u spp in %.2f s, %.2f Mrays/s\n", a.scene.c_str(),
              a.out.c_str(), s.width, s.height, result.stats.spp, result.stats.seconds,
              stats["rays_per_second"].get<double>() * 1e-6);
  return finishContext(*ctx);
}

}  // namespace

std::function<int()> addRenderCommand(CLI::App& app, const CommonOptions& common) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand("render", "render one image headless");
  cmd->add_option("--scene", args->scene, "glTF scene (.gltf or .glb)")->required();
  cmd->add_option("--out", args->out, "output image (.png, .pfm or .exr)")->required();
  cmd->add_option("--spp", args->spp, "samples per pixel")->check(CLI::Range(1, 1 << 20));
  args->settings.samplesPerFrame = 4;
  // --spp-per-frame as in the demo and the settings file.
  cmd->add_option("--batch,--spp-per-frame", args->settings.samplesPerFrame,
                  "samples per pixel per GPU submission")
      ->check(wholeRange(ranges::kSamplesPerFrame));
  cmd->add_option("--time", args->time, "animation time in seconds")->check(finiteRange(0.0, 1e6));
  cmd->add_option("--stats-json", args->statsJson, "write render statistics here");
  addRenderOptions(*cmd, args->settings);
  addGuidingOptions(*cmd, args->guiding, args->guidingCli);
  addEnvironmentOptions(*cmd, args->environment, args->skyText);
  addSettingsOption(*cmd, args->settingsFile);
  return [cmd, args, &common]() -> int {
    if (!cmd->parsed()) return -1;
    Settings file{args->settings, args->guiding, {}, args->environment};
    applySettingsFile(*cmd, args->settingsFile, file);
    args->settings = file.render;
    args->guiding = file.guiding;
    args->environment = file.environment;
    finishEnvironmentOptions(*cmd, args->skyText, args->environment);
    return runRender(*args, common);
  };
}

}  // namespace qlight::game
