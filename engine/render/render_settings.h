// Settings of the path tracer that a user can change (CLI, UI).
#pragma once
#include <cstdint>

#include "engine/image/image_io.h"

namespace qlight::render {

enum class Estimator : uint32_t {
  Mis,       // NEE and BSDF sampling, combined by the power heuristic (default)
  BsdfOnly,  // no NEE: light is found only by scattered rays
  NeeOnly,   // only NEE (and emitters seen directly by the camera)
};

struct RenderSettings {
  uint32_t width = 320;
  uint32_t height = 180;
  uint32_t samplesPerFrame = 1;
  uint32_t maxDepth = 8;  // bounces: 0 = emitters only, 1 = direct light
  uint32_t seed = 1;
  Estimator estimator = Estimator::Mis;
  bool russianRoulette = true;
  float exposure = 1.0f;
  // When lights or objects move: 0 restarts accumulation, k in (0, 1) keeps the
  // accumulated samples weighted by k (temporal blending: less noise, some lag).
  float temporalBlend = 0.0f;
  image::Tonemap tonemap = image::Tonemap::Aces;
};

}  // namespace qlight::render
