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
// The bounces a shade pipeline shades (kBouncePhase*): each bounce's steps that the others
// lack are left out of the others' pipelines.
#define QL_SPEC_BOUNCE_PHASE 18
// The paths record learning targets (Q, NEE counts, light values); else (frozen) that code is out.
#define QL_SPEC_LEARN 19
// The shade pass traces the extension ray of the hit it shades (no trace pass, no hit stored).
#define QL_SPEC_TRACE_IN_SHADE 20
// Some material has a microfacet lobe (metal, a dielectric specular layer or transmission); else
// every surface is exactly Lambertian and the BSDF is its short code (shared/bsdf.h).
#define QL_SPEC_USE_MICROFACET 21

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
QL_CONST uint kSpecBouncePhase = QL_SPEC_BOUNCE_PHASE;
QL_CONST uint kSpecLearn = QL_SPEC_LEARN;
QL_CONST uint kSpecTraceInShade = QL_SPEC_TRACE_IN_SHADE;
QL_CONST uint kSpecUseMicrofacet = QL_SPEC_USE_MICROFACET;
QL_CONST uint kSpecPathFeatureCount = QL_SPEC_USE_MICROFACET + 1u;  // values to pass

// Values of kSpecBouncePhase.
QL_CONST uint kBouncePhaseAny = 0u;     // whichever bounce the push constant names
QL_CONST uint kBouncePhaseCamera = 1u;  // bounce 0: the camera rays' hits
QL_CONST uint kBouncePhaseSecond = 2u;  // bounce 1
QL_CONST uint kBouncePhaseLater = 3u;   // bounces 2 and on (Russian roulette's)
QL_FN uint bouncePhaseOf(uint bounce) {
  return bounce == 0u ? kBouncePhaseCamera : bounce == 1u ? kBouncePhaseSecond : kBouncePhaseLater;
}
QL_END

#endif
