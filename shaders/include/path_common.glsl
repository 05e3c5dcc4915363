// What every wavefront path tracing pass includes: the shared structs and
// math, the scene, lights and guiding buffers, the frame, and the path state.
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
#include "shared/scene_types.h"
#include "shared/guiding_types.h"
#include "shared/random.h"
#include "shared/sampling.h"
#include "include/features.glsl"
#define QL_BSDF_MICROFACET kUseMicrofacet
#include "shared/bsdf.h"
#include "shared/tonemap.h"
#include "shared/ray_offset.h"
#include "include/scene_access.glsl"
#include "include/lights.glsl"
#include "include/guiding.glsl"

layout(local_size_x = QL_PATH_GROUP_SIZE) in;
layout(binding = QL_BIND_FRAME, scalar) readonly buffer Frame { FrameUniforms frame; };
layout(push_constant, scalar) uniform Push { TracePush pc; };
#include "include/path_state.glsl"

// The bounce being shaded, where the pipeline is specialized on it (kBouncePhase) a constant:
// code that only some bounces run is then absent from the others (lavapipe would run it masked).
bool atCameraHit() {
  return kBouncePhase == kBouncePhaseAny ? pc.bounce == 0u : kBouncePhase == kBouncePhaseCamera;
}
bool atRouletteBounce() {  // bounces 2 and on
  return kBouncePhase == kBouncePhaseAny ? pc.bounce >= 2u : kBouncePhase == kBouncePhaseLater;
}

const float kInfinity = 1e30;
