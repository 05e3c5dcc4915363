#version 460
// Benchmark kernel: traces one ray per invocation (camera rays, or random
// directions from random points inside the scene bounds) and counts hits, to
// measure traversal speed apart from shading (bench/trace.cpp).
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require
#include "shared/scene_types.h"
#include "shared/random.h"
#include "shared/sampling.h"
#include "shared/bsdf.h"
#include "shared/tonemap.h"
#include "shared/trace_bench.h"
#include "include/scene_access.glsl"
#include "include/lights.glsl"

layout(local_size_x = 64) in;
layout(binding = QL_BIND_FRAME, scalar) readonly buffer Frame { FrameUniforms frame; };
layout(binding = QL_BIND_STATS) buffer Stats { uint stats[]; };
layout(push_constant, scalar) uniform Push { TraceBenchPush pc; };

void main() {
  uint id = gl_GlobalInvocationID.x;
  if (id >= pc.rayCount) return;
  Rng rng = rngSeed(id, frame.frameIndex, frame.seed);
  vec3 origin, dir;
  if (pc.mode == 0u) {  // camera rays in scanline order (coherent)
    uvec2 pixel = uvec2(id % frame.resolution.x, id / frame.resolution.x);
    vec2 ndc = (vec2(pixel) + 0.5) / vec2(frame.resolution) * 2.0 - 1.0;
    GpuCamera cam = frame.camera;
    dir = normalize(cam.forward + ndc.x * cam.tanHalfFovY * cam.aspect * cam.right - ndc.y * cam.tanHalfFovY * cam.up);
    origin = cam.position;
  } else {  // incoherent: random origins near the center, random directions
    origin = frame.sceneCenter + (rngNext3(rng) - 0.5) * frame.sceneRadius * 0.5;
    dir = sampleUniformSphere(rngNext2(rng));
  }
  bool hit;
  if (pc.mode == 2u) {
    hit = traceAny(origin, dir, frame.sceneRadius);
  } else {
    BvhHit h;
    hit = traceClosest(origin, dir, 1e30, h);
  }
  if (hit) atomicAdd(stats[0], 1u);
}
