// What every wavefront path tracing pass includes: the shared structs and
// math, the scene, lights and guiding buffers, the frame, and the path state.
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "shared/scene_types.h"
#include "shared/guiding_types.h"
#include "shared/random.h"
#include "shared/sampling.h"
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

const float kInfinity = 1e30;
