// The display filter's bindings and uniforms, shared by shaders/gbuffer.comp,
// shaders/temporal_reuse.comp, shaders/atrous.comp and engine/ui/display_filter.cpp.
#ifndef QLIGHT_UI_DISPLAY_FILTER_TYPES_H
#define QLIGHT_UI_DISPLAY_FILTER_TYPES_H
#include "../../shaders/shared/scene_types.h"

// gbuffer.comp (besides the scene's surface bindings, QL_BIND_*): the primary hit per pixel.
#define QL_FILTER_BIND_UNIFORMS 40
#define QL_FILTER_BIND_GBUFFER 41  // rgba32f: shading normal, distance from the camera (0: none)
#define QL_FILTER_BIND_ALBEDO 42   // rgba32f: base colour of the primary hit (1 where none)
// temporal_reuse.comp
#define QL_FILTER_BIND_ACCUM 43  // the tracer's accumulation: rgb sum, a count
#define QL_FILTER_BIND_PREV_GBUFFER 44
#define QL_FILTER_BIND_PREV_OUTPUT 45  // last frame's output: rgb sum, a weight
#define QL_FILTER_BIND_HISTORY 46      // what the current accumulation adds to: rgb mean, a weight
#define QL_FILTER_BIND_OUTPUT 47       // rgb sum, a weight (the display's format)
// atrous.comp
#define QL_ATROUS_BIND_INPUT 48
#define QL_ATROUS_BIND_OUTPUT 49

QL_BEGIN
struct FilterUniforms {
  GpuCamera camera;          // this frame's
  GpuCamera previousCamera;  // the last frame's
  uint restarted;            // the tracer's accumulation restarted this frame
  uint reproject;            // reuse the last frame's output where it is still visible
  float historyKeep;         // weight kept of the history when the accumulation went on
  float historyMax;          // most frames of weight a reprojected history keeps
};
QL_CHECK_SIZE(FilterUniforms, 144);

// One a-trous wavelet iteration (Dammertz et al. 2010): a 5x5 B3-spline kernel with holes
// of `step` pixels, stopped at edges of normal, depth, albedo and colour.
struct AtrousPush {
  int step;
  float colourSigma;   // scale of the relative luminance difference allowed (larger: smoother)
  uint first;          // divide by albedo (filter the irradiance), clamp fireflies
  uint last;           // multiply the albedo back
  float maxLuminance;  // first pass: brighter pixels are scaled down to this (display only)
  uint pad0, pad1, pad2;
};
QL_CHECK_SIZE(AtrousPush, 32);
QL_END

#endif
