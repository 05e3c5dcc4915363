// Push constants of shaders/trace_bench.comp, the traversal benchmark kernel
// (bench/trace.cpp). It binds the scene block and QL_BIND_FRAME / QL_BIND_STATS
// of bindings.h.
#ifndef QLIGHT_SHARED_TRACE_BENCH_H
#define QLIGHT_SHARED_TRACE_BENCH_H
#include "common.h"

QL_BEGIN
struct TraceBenchPush {
  uint rayCount;
  uint mode;  // 0: camera rays, 1: incoherent closest hit, 2: incoherent shadow rays
  uint pad0;
  uint pad1;
};
QL_CHECK_SIZE(TraceBenchPush, 16);
QL_END

#endif
