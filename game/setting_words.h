// The words and ranges of the user settings, shared by the command line and the settings
// file so that both accept the same values ("mis", "aces", "photon", "returns"...).
#pragma once
#include <map>
#include <string>

#include "engine/guiding/guiding_settings.h"
#include "engine/image/image_io.h"
#include "engine/render/render_settings.h"

namespace qlight::game {

template <class T>
using Words = std::map<std::string, T>;

inline const Words<render::Estimator>& estimatorWords() {
  static const Words<render::Estimator> words{{"mis", render::Estimator::Mis},
                                              {"bsdf", render::Estimator::BsdfOnly},
                                              {"nee", render::Estimator::NeeOnly}};
  return words;
}

inline const Words<render::TraceKernel>& traceKernelWords() {
  static const Words<render::TraceKernel> words{{"auto", render::TraceKernel::Auto},
                                                {"fused", render::TraceKernel::Fused},
                                                {"separate", render::TraceKernel::Separate}};
  return words;
}

inline const Words<image::Tonemap>& tonemapWords() {
  static const Words<image::Tonemap> words{{"aces", image::Tonemap::Aces},
                                           {"clamp", image::Tonemap::Clamp}};
  return words;
}

inline const Words<guiding::PointSet>& pointSetWords() {
  static const Words<guiding::PointSet> words{{"photon", guiding::PointSet::PhotonMap},
                                              {"poisson", guiding::PointSet::PoissonAo}};
  return words;
}

inline const Words<guiding::DirectionModel>& directionModelWords() {
  static const Words<guiding::DirectionModel> w{{"tree", guiding::DirectionModel::Tree},
                                                {"strata", guiding::DirectionModel::Strata}};
  return w;
}

inline const Words<guiding::GuideMethod>& guideMethodWords() {
  static const Words<guiding::GuideMethod> words{{"q", guiding::GuideMethod::Q},
                                                 {"dqn", guiding::GuideMethod::Dqn}};
  return words;
}

inline const Words<guiding::LearningTarget>& learningTargetWords() {
  static const Words<guiding::LearningTarget> words{{"returns", guiding::LearningTarget::Returns},
                                                    {"td", guiding::LearningTarget::TdStep}};
  return words;
}

inline const Words<bool>& onOffWords() {
  static const Words<bool> words{{"on", true}, {"off", false}};
  return words;
}

// The word for `value` ("" when it has none).
template <class T>
std::string wordOf(const Words<T>& words, T value) {
  for (const auto& [word, v] : words)
    if (v == value) return word;
  return "";
}

// The accepted values of a numeric setting, bounds included.
struct Range {
  double lowest, highest;
};

namespace ranges {
inline constexpr Range kImageSize{1, 16384};
inline constexpr Range kMaxDepth{0, 1024};
inline constexpr Range kSamplesPerFrame{1, 4096};
inline constexpr Range kExposure{1e-6, 1e6};
inline constexpr Range kTemporalBlend{0, 0.99};
inline constexpr Range kHalfLife{0, 1e6};
inline constexpr Range kForgetOnLightMove{0, 1e3};
inline constexpr Range kNeeMinProbability{0.01, 1};
inline constexpr Range kDqnLearningRate{1e-7, 1};
inline constexpr Range kRenderScale{0.1, 1};
inline constexpr Range kTargetFrameMs{0, 10000};
inline constexpr Range kEnvStrength{0, 1e6};
inline constexpr Range kEnvRotation{-36000, 36000};  // degrees
inline constexpr Range kSkyRadiance{0, 1e6};
}  // namespace ranges

}  // namespace qlight::game
