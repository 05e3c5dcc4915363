// Scene and frame features the path tracing passes are specialized on. On
// lavapipe both sides of every branch execute (masked SIMD), so code for a
// feature the frame does not use must not be in the pipeline at all: a
// specialization constant set to false removes it at pipeline creation.
#ifndef QLIGHT_FEATURES_GLSL
#define QLIGHT_FEATURES_GLSL
#include "shared/specialization.h"
layout(constant_id = QL_SPEC_USE_TEXTURES) const bool kUseTextures = true;
layout(constant_id = QL_SPEC_USE_GUIDING) const bool kUseGuiding = true;
layout(constant_id = QL_SPEC_USE_LIGHT_LEARNING) const bool kUseLightLearning = true;
// Punctual, directional and sky lights (else triangles only).
layout(constant_id = QL_SPEC_USE_NON_TRIANGLE_LIGHTS) const bool kUseNonTriangleLights = true;
// TEXCOORD_1, COLOR_0 and tangents (GpuVertexExtras) of some mesh.
layout(constant_id = QL_SPEC_USE_VERTEX_EXTRAS) const bool kUseVertexExtras = true;
// The sky is an environment map (shared/environment.h), else uniform.
layout(constant_id = QL_SPEC_USE_ENVIRONMENT_MAP) const bool kUseEnvironmentMap = true;
// Materials with alphaMode MASK or BLEND: traversal tests their alpha at each candidate hit.
layout(constant_id = QL_SPEC_USE_ALPHA_TEST) const bool kUseAlphaTest = true;
// Deep Q guiding: the network at each vertex instead of the cache points' tables.
layout(constant_id = QL_SPEC_USE_DQN) const bool kUseDqn = false;
// Direction trees per point (--directions tree) instead of the strata.
layout(constant_id = QL_SPEC_USE_DIRECTION_TREES) const bool kUseDirectionTrees = false;
// D&K's one-step TD target (--learning-target td): its Q lookups at every vertex, else returns.
layout(constant_id = QL_SPEC_USE_TD_TARGET) const bool kUseTdTarget = false;
// The deep Q network's shape (with kUseDqn).
layout(constant_id = QL_SPEC_DQN_BINS) const uint kDqnBins = 16u;
layout(constant_id = QL_SPEC_DQN_WIDTH) const uint kDqnWidth = 16u;
layout(constant_id = QL_SPEC_DQN_HIDDEN) const uint kDqnHidden = 1u;
layout(constant_id = QL_SPEC_DQN_OUTPUTS) const uint kDqnOutputs = 64u;
// Cells per axis of its baked grid; 0: the paths evaluate the network at every vertex.
layout(constant_id = QL_SPEC_DQN_GRID) const uint kDqnGrid = 0u;
// The bounces this pipeline shades (kBouncePhase* in shared/specialization.h; path_common.glsl's
// atCameraHit and atRouletteBounce read it).
layout(constant_id = QL_SPEC_BOUNCE_PHASE) const uint kBouncePhase = 0u;
// The guide learns: the paths record Q targets (returns or TD), NEE counts and light values.
// A frozen guide's pipelines leave that code out.
layout(constant_id = QL_SPEC_LEARN) const bool kLearning = true;
// The shade pass traces the ray to the hit it shades itself (fused), else the trace pass did.
layout(constant_id = QL_SPEC_TRACE_IN_SHADE) const bool kTraceInShade = false;
// Some material is not exactly Lambertian (path_common.glsl hands it to shared/bsdf.h).
layout(constant_id = QL_SPEC_USE_MICROFACET) const bool kUseMicrofacet = true;
#endif
