// Specialization constant ids, shared by the GLSL layout(constant_id = ...)
// qualifiers and the C++ that fills the values (gpu::ComputePipeline takes
// value i for constant_id i). Ids 0..2 are reserved: by gpu::ComputePipeline's
// convention they are the workgroup size (local_size_x_id = 0..2).
#ifndef QLIGHT_SHARED_SPECIALIZATION_H
#define QLIGHT_SHARED_SPECIALIZATION_H
#include "common.h"

// Features of the path tracing passes (shaders/include/features.glsl). GLSL
// layout qualifiers need literals, hence macros.
#define QL_SPEC_USE_TEXTURES 3
#define QL_SPEC_USE_GUIDING 4
#define QL_SPEC_USE_LIGHT_LEARNING 5
#define QL_SPEC_USE_NON_TRIANGLE_LIGHTS 6
#define QL_SPEC_USE_VERTEX_EXTRAS 7
#define QL_SPEC_USE_ENVIRONMENT_MAP 8
#define QL_SPEC_USE_ALPHA_TEST 9
#define QL_SPEC_USE_DQN 10
#define QL_SPEC_USE_DIRECTION_TREES 11
#define QL_SPEC_USE_TD_TARGET 12
// The deep Q network's shape (shared/dqn.h DqnShape): known when the pipeline is made, its
// loops have fixed counts and its activations fixed places (on lavapipe an array indexed by
// a runtime value is read lane by lane).
#define QL_SPEC_DQN_BINS 13
#define QL_SPEC_DQN_WIDTH 14
#define QL_SPEC_DQN_HIDDEN 15
#define QL_SPEC_DQN_OUTPUTS 16
#define QL_SPEC_DQN_GRID 17  // cells per axis of the network's baked grid (0: none)

QL_BEGIN
QL_CONST uint kSpecUseTextures = QL_SPEC_USE_TEXTURES;
QL_CONST uint kSpecUseGuiding = QL_SPEC_USE_GUIDING;
QL_CONST uint kSpecUseLightLearning = QL_SPEC_USE_LIGHT_LEARNING;
QL_CONST uint kSpecUseNonTriangleLights = QL_SPEC_USE_NON_TRIANGLE_LIGHTS;
QL_CONST uint kSpecUseVertexExtras = QL_SPEC_USE_VERTEX_EXTRAS;
QL_CONST uint kSpecUseEnvironmentMap = QL_SPEC_USE_ENVIRONMENT_MAP;
QL_CONST uint kSpecUseAlphaTest = QL_SPEC_USE_ALPHA_TEST;
QL_CONST uint kSpecUseDqn = QL_SPEC_USE_DQN;
QL_CONST uint kSpecUseDirectionTrees = QL_SPEC_USE_DIRECTION_TREES;
QL_CONST uint kSpecUseTdTarget = QL_SPEC_USE_TD_TARGET;
QL_CONST uint kSpecDqnBins = QL_SPEC_DQN_BINS;
QL_CONST uint kSpecDqnWidth = QL_SPEC_DQN_WIDTH;
QL_CONST uint kSpecDqnHidden = QL_SPEC_DQN_HIDDEN;
QL_CONST uint kSpecDqnOutputs = QL_SPEC_DQN_OUTPUTS;
QL_CONST uint kSpecDqnGrid = QL_SPEC_DQN_GRID;
QL_CONST uint kSpecPathFeatureCount = QL_SPEC_DQN_GRID + 1u;  // values to pass
QL_END

#endif
