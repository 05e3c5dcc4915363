// The display pass's bindings and push constants, shared by shaders/display.comp
// (scalar block layout) and engine/ui/display_pass.cpp.
#ifndef QLIGHT_UI_DISPLAY_TYPES_H
#define QLIGHT_UI_DISPLAY_TYPES_H
#include "../../shaders/shared/common.h"

#define QL_DISPLAY_BIND_ACCUM 0
#define QL_DISPLAY_BIND_OUTPUT 1

QL_BEGIN
struct DisplayPush {
  float exposure;
  uint tonemap;     // kTonemapClamp or kTonemapAces (shared/tonemap.h)
  uint encodeSrgb;  // 0: the swapchain encodes sRGB itself, so store linear values
  uint pad0;
};
QL_CHECK_SIZE(DisplayPush, 16);
QL_END

#endif
