// The accumulation fade's binding and push constants, shared by
// shaders/accum_decay.comp (scalar block layout) and engine/render/path_tracer.cpp.
#ifndef QLIGHT_SHARED_ACCUM_DECAY_H
#define QLIGHT_SHARED_ACCUM_DECAY_H
#include "common.h"

#define QL_ACCUM_DECAY_BIND_ACCUM 0

QL_BEGIN
struct AccumDecayPush {
  float factor;  // weight kept of the accumulated sums (and sample counts)
  uint width;
  uint height;
  uint pad;
};
QL_CHECK_SIZE(AccumDecayPush, 16);
QL_END

#endif
