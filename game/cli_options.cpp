#include "game/cli_options.h"

#include <cmath>
#include <map>

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

void addRenderOptions(CLI::App& app, render::RenderSettings& s) {
  app.add_option("--width", s.width, "image width in pixels")->check(CLI::Range(1, 16384));
  app.add_option("--height", s.height, "image height in pixels")->check(CLI::Range(1, 16384));
  addTracingOptions(app, s);
  app.add_option("--exposure", s.exposure, "exposure multiplier for PNG and display")
      ->check(finiteRange(1e-6, 1e6));
  app.add_option(
         "--temporal-blend", s.temporalBlend,
         "animated scenes: weight kept of the accumulated image when things move (0: restart)")
      ->check(finiteRange(0.0, 0.99));
  std::map<std::string, image::Tonemap> tonemaps{{"aces", image::Tonemap::Aces},
                                                 {"clamp", image::Tonemap::Clamp}};
  app.add_option("--tonemap", s.tonemap, "aces or clamp (PNG and display only)")
      ->transform(CLI::CheckedTransformer(tonemaps, CLI::ignore_case));
}

void addTracingOptions(CLI::App& app, render::RenderSettings& s) {
  app.add_option("--seed", s.seed, "random seed (same seed, same image)");
  app.add_option("--max-depth", s.maxDepth, "bounces: 0 = emitters only, 1 = direct light")
      ->check(CLI::Range(0, 1024));
  std::map<std::string, render::Estimator> estimators{{"mis", render::Estimator::Mis},
                                                      {"bsdf", render::Estimator::BsdfOnly},
                                                      {"nee", render::Estimator::NeeOnly}};
  app.add_option("--estimator", s.estimator, "mis (NEE + BSDF, power heuristic), bsdf or nee")
      ->transform(CLI::CheckedTransformer(estimators, CLI::ignore_case));
  std::map<std::string, bool> onOff{{"on", true}, {"off", false}};
  app.add_option("--rr", s.russianRoulette, "Russian roulette: on|off")
      ->transform(CLI::CheckedTransformer(onOff, CLI::ignore_case));
}

void addGuidingOptions(CLI::App& app, guiding::GuidingSettings& g, GuidingCli& cli) {
  std::map<std::string, bool> guidingModes{{"q", true}, {"off", false}};
  app.add_option("--guiding", g.enabled, "q (Q-learned importance sampling) or off")
      ->transform(CLI::CheckedTransformer(guidingModes, CLI::ignore_case));
  app.add_option("--strata", cli.strata, "hemisphere strata RxC, e.g. 8x8 or 16x8");
  app.add_option("--alpha-min", g.alphaMin, "learning rate floor (keeps tracking moving lights)");
  app.add_option("--alpha-max", g.alphaMax, "learning rate ceiling");
  app.add_option("--half-life", g.halfLifeFrames,
                 "tracking: frames after which what was learned counts half (0: never forget)")
      ->check(finiteRange(0.0, 1e6));
  app.add_option("--points", g.pointBudget,
                 "cache point budget (default 0: one point per 8 paths per frame, 256..16384)");
  app.add_option("--select-probability", g.selectProbability,
                 "share of guided samples at diffuse vertices, 0..0.95 (BSDF sampling the rest)");
  app.add_option("--confidence-updates", g.confidenceUpdates,
                 "Q updates per stratum before a point guides at the full share (0: at once)");
  std::map<std::string, guiding::LearningTarget> targets{
      {"returns", guiding::LearningTarget::Returns}, {"td", guiding::LearningTarget::TdStep}};
  app.add_option("--learning-target", g.target,
                 "returns (radiance each direction brought back, NEE included) or td (D&K's "
                 "one-step target)")
      ->transform(CLI::CheckedTransformer(targets, CLI::ignore_case));
  std::map<std::string, guiding::PointSet> sets{{"photon", guiding::PointSet::PhotonMap},
                                                {"poisson", guiding::PointSet::PoissonAo}};
  app.add_option("--point-set", g.pointSet,
                 "photon (fixed rejection distance) or poisson (distance from ambient occlusion)")
      ->transform(CLI::CheckedTransformer(sets, CLI::ignore_case));
  std::map<std::string, bool> onOff{{"on", true}, {"off", false}};
  app.add_option("--light-learning", g.lightLearning, "learned light selection for NEE: on|off")
      ->transform(CLI::CheckedTransformer(onOff, CLI::ignore_case));
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

}  // namespace qlight::game
