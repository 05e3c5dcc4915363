// The binding numbers (set 0) of the path tracing passes (shaders/pt_*.comp)
// and of the other passes that bind the scene block (guiding darts, traversal
// benchmark): GLSL declares its resources and C++ binds them by these names.
// One contiguous group per binder: the scene, the path tracer's own buffers,
// and the guide's.
//
// Passes with a set of their own (q_update, prefix sum, accumulation fade,
// display) name their slots next to their push constants:
// guiding_types.h, prefix_sum.h, accum_decay.h, engine/ui/display_types.h.
#ifndef QLIGHT_SHARED_BINDINGS_H
#define QLIGHT_SHARED_BINDINGS_H

// --- scene: GpuScene::bind (BVH, triangles, materials, textures, lights) ---
#define QL_BIND_BVH_NODES 0
#define QL_BIND_BVH_TRIS 1
#define QL_BIND_BVH_INSTANCES 2
#define QL_BIND_TRIANGLES 3
#define QL_BIND_VERTICES 4
#define QL_BIND_INSTANCES 5
#define QL_BIND_MATERIALS 6
#define QL_BIND_TEXTURES 7
#define QL_BIND_TEXELS 8
#define QL_BIND_LIGHTS 9
#define QL_BIND_LIGHT_CDF 10

// --- frame and paths: bound by the path tracer itself ---
#define QL_BIND_FRAME 11       // FrameUniforms
#define QL_BIND_ACCUM 12       // accumulation image (pt_end)
#define QL_BIND_STATS 13       // kStat* counters (pt_end)
#define QL_BIND_PATH_STATE 14  // kPathStateTexels texels per path (scene_types.h)
// Work queues of path ids: trace and shade visit the current one, shade (and
// begin) fill the next; QL_BIND_QUEUE_STATE holds both counts (QueueState[2]).
#define QL_BIND_QUEUE_IN 15
#define QL_BIND_QUEUE_OUT 16
#define QL_BIND_QUEUE_STATE 17

// --- guide bindings: what a guide provides to the path passes ---
// The path passes declare them always, so a frame without guiding binds the
// null guide's placeholders (specialization removes the code that reads them).
// In C++ only engine/guiding/guide_bindings.cpp binds them.
#define QL_BIND_GUIDING 18  // GuidingUniforms
#define QL_BIND_CACHE_POINTS 19
#define QL_BIND_GRID_BUCKETS 20
#define QL_BIND_GRID_POINTS 21
#define QL_BIND_Q_CDF 22
#define QL_BIND_Q_SUM 23  // Q-learning targets, fixed point (lo, hi) pairs
#define QL_BIND_Q_COUNT 24
#define QL_BIND_SPAWN 25  // uncovered camera hits, candidates for new points
#define QL_BIND_V_CDF 26  // learned light selection V(point, light)
#define QL_BIND_V_SUM 27
#define QL_BIND_V_COUNT 28
#define QL_BIND_POINT_UPDATES 29  // Q updates each point has received
#define QL_BIND_Q_CHILDREN 35     // direction trees: each slot's child node (0: a leaf)
#define QL_BIND_NEE_COUNTS 36     // shadow rays per point, and those unoccluded (guiding_types.h)

// --- guiding darts (guiding_darts.comp): the scene block, and its output ---
#define QL_BIND_DART_CANDIDATES 30

// --- ray lists of trace_rays.comp (bench/traversal_vs_embree): the BVH block, and these ---
#define QL_BIND_TRACE_RAYS 31
#define QL_BIND_TRACE_HITS 32

// --- scene, continued: the environment map (GpuScene::bind; layout in environment.h) ---
#define QL_BIND_ENV_TEXELS 33  // header, then (radiance, density) per pixel
#define QL_BIND_ENV_CDF 34     // conditional CDFs per row, then the marginal

#endif
