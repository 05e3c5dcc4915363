// The display filter's per-frame values (cameras, restart and reprojection flags), as the
// gbuffer and temporal-reuse passes read them. A storage buffer, not a uniform block: this
// lavapipe (Mesa 22.3) inlines uniform-block values that decide a branch and recompiles the
// shader at each dispatch where that pays; with the camera in the block that was 80-90 ms of
// LLVM a moving frame (docs/performance_log.md).
#include "../engine/ui/display_filter_types.h"
layout(binding = QL_FILTER_BIND_UNIFORMS, scalar) readonly buffer Uniforms { FilterUniforms u; };
