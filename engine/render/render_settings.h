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

// Where a bounce's extension rays are traced. On a CPU device (lavapipe) fused is faster: the
// hit never goes through memory, and each texel stored there costs more than the rays'
// traversal gains from a small kernel. On a GPU the wavefront's small trace kernel keeps
// occupancy high (Laine et al. 2013), so separate is the default there.
enum class TraceKernel : uint32_t {
  Auto,      // fused on a CPU device, separate on a GPU
  Fused,     // the shade pass traces the ray to the hit it shades
  Separate,  // a trace pass per bounce writes each hit for the shade pass
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
  TraceKernel traceKernel = TraceKernel::Auto;  // the image is the same either way
};

}  // namespace qlight::render
