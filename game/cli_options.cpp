#include "game/cli_options.h"

#include <cmath>
#include <cstdio>

#include "game/environment_choice.h"
#include "game/setting_words.h"
#include "game/settings_file.h"

namespace qlight::game {

CLI::Validator finiteRange(double lowest, double highest) {
  const std::string range =
      "[" + CLI::detail::to_string(lowest) + " - " + CLI::detail::to_string(highest) + "]";
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        double value = 0;
        if (!CLI::detail::lexical_cast(text, value)) return "not a number: " + text;
        if (!std::isfinite(value) || value < lowest || value > highest)
          return "value " + text + " not in range " + range;
        return {};
      },
      "FLOAT in " + range);
}

CLI::Validator finiteRange(Range r) { return finiteRange(r.lowest, r.highest); }

CLI::Validator wholeRange(Range r) { return CLI::Range(int64_t(r.lowest), int64_t(r.highest)); }

void addRenderOptions(CLI::App& app, render::RenderSettings& s) {
  app.add_option("--width", s.width, "image width in pixels")
      ->check(wholeRange(ranges::kImageSize));
  app.add_option("--height", s.height, "image height in pixels")
      ->check(wholeRange(ranges::kImageSize));
  addTracingOptions(app, s);
  app.add_option("--exposure", s.exposure, "exposure multiplier for PNG and display")
      ->check(finiteRange(ranges::kExposure));
  app.add_option(
         "--temporal-blend", s.temporalBlend,
         "animated scenes: weight kept of the accumulated image when things move (0: restart)")
      ->check(finiteRange(ranges::kTemporalBlend));
  app.add_option("--tonemap", s.tonemap, "aces or clamp (PNG and display only)")
      ->transform(CLI::CheckedTransformer(tonemapWords(), CLI::ignore_case));
}

void addTracingOptions(CLI::App& app, render::RenderSettings& s) {
  app.add_option("--seed", s.seed, "random seed (same seed, same image)");
  app.add_option("--max-depth", s.maxDepth, "bounces: 0 = emitters only, 1 = direct light")
      ->check(wholeRange(ranges::kMaxDepth));
  app.add_option("--estimator", s.estimator, "mis (NEE + BSDF, power heuristic), bsdf or nee")
      ->transform(CLI::CheckedTransformer(estimatorWords(), CLI::ignore_case));
  app.add_option("--rr", s.russianRoulette, "Russian roulette: on|off")
      ->transform(CLI::CheckedTransformer(onOffWords(), CLI::ignore_case));
  app.add_option("--trace-kernel", s.traceKernel,
                 "extension rays traced in the shade pass (fused) or a pass of their own "
                 "(separate); auto: fused on a CPU device, separate on a GPU (same image)")
      ->transform(CLI::CheckedTransformer(traceKernelWords(), CLI::ignore_case));
}

void addGuidingOptions(CLI::App& app, guiding::GuidingSettings& g, GuidingCli& cli) {
  app.add_option_function<std::string>(
         "--guiding",
         [&g](const std::string& word) {
           std::string w = word;
           for (char& c : w) c = char(std::tolower(static_cast<unsigned char>(c)));
           g.enabled = w != "off";
           if (g.enabled) g.method = guideMethodWords().at(w);
         },
         "q (Q-learned importance sampling in cache points), dqn (a network of the "
         "continuous state, trained on the GPU) or off")
      ->check(CLI::IsMember({"q", "dqn", "off"}, CLI::ignore_case));
  app.add_option("--dqn-width", g.dqnWidth, "deep Q: neurons per hidden layer (4..128, x4)");
  app.add_option("--dqn-layers", g.dqnHidden, "deep Q: hidden layers (1..4)");
  app.add_option("--dqn-bins", g.dqnBins, "deep Q: one-blob bins per position axis (1..32)");
  app.add_option("--dqn-batch", g.dqnBatch, "deep Q: records per training step");
  app.add_option("--dqn-steps", g.dqnStepsPerFrame, "deep Q: training steps per frame");
  app.add_option("--dqn-learning-rate", g.dqnLearningRate, "deep Q: Adam's learning rate")
      ->check(finiteRange(ranges::kDqnLearningRate));
  app.add_option("--dqn-target-interval", g.dqnTargetInterval,
                 "deep Q: frames between target network updates");
  app.add_option("--dqn-grid", g.dqnGrid,
                 "deep Q: bake the network into a grid of N^3 cells at each target update and "
                 "sample from the cells (2..32; 0: evaluate it at every path vertex)");
  app.add_option("--strata", cli.strata, "hemisphere strata RxC, e.g. 8x8 or 16x8");
  app.add_option("--directions", g.directions,
                 "tree (a quadtree per point that refines where Q is) or strata (D&K's RxC)")
      ->transform(CLI::CheckedTransformer(directionModelWords(), CLI::ignore_case));
  app.add_option("--tree-nodes", g.treeNodes, "direction tree: nodes per point (5..128)");
  app.add_option("--tree-split", g.treeSplitShare,
                 "direction tree: a leaf with more than this share of its point's Q splits");
  app.add_option("--alpha-min", g.alphaMin, "learning rate floor (keeps tracking moving lights)");
  app.add_option("--alpha-max", g.alphaMax, "learning rate ceiling");
  app.add_option("--half-life", g.halfLifeFrames,
                 "tracking: frames after which a point's confidence counts half and its Q's visits "
                 "a quarter (0: never forget)")
      ->check(finiteRange(ranges::kHalfLife));
  app.add_option("--forget-on-light-move", g.forgetOnLightMove,
                 "tracking: halvings of the confidence per scene radius a light moves, twice as "
                 "many of Q (0: off)")
      ->check(finiteRange(ranges::kForgetOnLightMove));
  app.add_option("--points", g.pointBudget,
                 "cache point budget (default 0: one point per 8 paths per frame, 256..16384)");
  app.add_option("--select-probability", g.selectProbability,
                 "share of guided samples at diffuse vertices, 0..0.95 (BSDF sampling the rest)");
  app.add_option("--confidence-updates", g.confidenceUpdates,
                 "Q updates per stratum before a point guides at the full share (0: at once)");
  app.add_option("--learning-target", g.target,
                 "returns (radiance each direction brought back, NEE included) or td (D&K's "
                 "one-step target)")
      ->transform(CLI::CheckedTransformer(learningTargetWords(), CLI::ignore_case));
  app.add_option("--point-set", g.pointSet,
                 "photon (fixed rejection distance) or poisson (distance from ambient occlusion)")
      ->transform(CLI::CheckedTransformer(pointSetWords(), CLI::ignore_case));
  app.add_option("--light-learning", g.lightLearning, "learned light selection for NEE: on|off")
      ->transform(CLI::CheckedTransformer(onOffWords(), CLI::ignore_case));
  app.add_option("--nee-min-probability", g.neeMinProbability,
                 "learned NEE: where a point's shadow rays are blocked, sample a light with this "
                 "probability only, 0.01..1 (default 0.1; 1: NEE at every vertex)")
      ->check(finiteRange(ranges::kNeeMinProbability));
  app.add_option("--guided-roulette", g.guidedRoulette,
                 "Russian roulette by the contribution Q expects (on) or by throughput: on|off")
      ->transform(CLI::CheckedTransformer(onOffWords(), CLI::ignore_case));
  app.add_option("--nee", cli.nee, "next event estimation: on (MIS with scattering) or off")
      ->check(CLI::IsMember({"on", "off"}, CLI::ignore_case));
}

void finishGuidingOptions(const GuidingCli& cli, guiding::GuidingSettings& g,
                          render::RenderSettings& r) {
  if (!cli.strata.empty()) guiding::parseStrata(cli.strata, g);
  if (cli.nee == "off") r.estimator = render::Estimator::BsdfOnly;
  if (cli.nee == "on" && r.estimator == render::Estimator::BsdfOnly)
    r.estimator = render::Estimator::Mis;
  g.seed = r.seed;
  guiding::validate(g);
}

void addEnvironmentOptions(CLI::App& app, EnvironmentSettings& env, std::string& skyText) {
  CLI::Option* file = app.add_option(
      "--env", env.file,
      "environment map: equirectangular .hdr or .exr, lighting the scene with its emitters");
  app.add_option("--sky", skyText, "uniform sky radiance R,G,B instead of a map (e.g. 1,1,1)")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            return parseSkyColor(text) ? "" : "not three numbers R,G,B in [0, 1e6]: " + text;
          },
          "R,G,B"))
      ->excludes(file);
  app.add_option("--env-strength", env.strength, "multiplies the environment map or sky")
      ->check(finiteRange(ranges::kEnvStrength));
  app.add_option("--env-rotation", env.rotationDegrees,
                 "turns the environment map about +Y, in degrees (right-handed)")
      ->check(finiteRange(ranges::kEnvRotation));
}

void finishEnvironmentOptions(const CLI::App& cmd, const std::string& skyText,
                              EnvironmentSettings& env) {
  if (cmd.count("--sky") > 0) {
    env.sky = parseSkyColor(skyText);
    env.file.clear();
  } else if (cmd.count("--env") > 0) {
    env.sky.reset();
  }
}

void addSettingsOption(CLI::App& app, std::string& file) {
  app.add_option("--settings", file,
                 "settings file (JSON) to start from; options given here override it");
}

void applySettingsFile(const CLI::App& cmd, const std::string& file, Settings& s) {
  if (file.empty()) return;
  auto given = [&cmd](const std::string& option) {
    const CLI::Option* o = cmd.get_option_no_throw(option);
    return o && o->count() > 0;
  };
  for (const std::string& warning : loadSettingsFile(file, s, given))
    std::fprintf(stderr, "qlight: warning: %s\n", warning.c_str());
}

}  // namespace qlight::game
