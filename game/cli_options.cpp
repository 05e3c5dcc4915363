#include "game/cli_options.h"

#include <map>

namespace qlight::game {

void addRenderOptions(CLI::App& app, render::RenderSettings& s) {
  app.add_option("--width", s.width, "image width in pixels")->check(CLI::Range(1, 16384));
  app.add_option("--height", s.height, "image height in pixels")->check(CLI::Range(1, 16384));
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
  app.add_option("--exposure", s.exposure, "exposure multiplier for PNG and display")
      ->check(CLI::PositiveNumber);
  std::map<std::string, render::Tonemap> tonemaps{{"aces", render::Tonemap::Aces},
                                                  {"clamp", render::Tonemap::Clamp}};
  app.add_option("--tonemap", s.tonemap, "aces or clamp (PNG and display only)")
      ->transform(CLI::CheckedTransformer(tonemaps, CLI::ignore_case));
}

}  // namespace qlight::game
