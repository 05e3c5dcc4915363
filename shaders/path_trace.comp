#version 460
// One sample per pixel of a unidirectional path tracer: BVH traversal in texel
// buffers, the glTF metallic-roughness BSDF, next event estimation combined with
// BSDF sampling by the power heuristic, Russian roulette. Adds the sample to the
// accumulation image (rgb: sum of radiance, a: sample count).
#extension GL_EXT_scalar_block_layout : require
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "shared/scene_types.h"
#include "shared/random.h"
#include "shared/sampling.h"
#include "shared/bsdf.h"
#include "shared/tonemap.h"
#include "shared/ray_offset.h"
#include "include/scene_access.glsl"
#include "include/lights.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = QL_BIND_FRAME, scalar) readonly buffer Frame { FrameUniforms frame; };
layout(binding = QL_BIND_ACCUM, rgba32f) uniform image2D uAccum;
layout(binding = QL_BIND_STATS) buffer Stats { uint stats[]; };
layout(push_constant, scalar) uniform Push { TracePush pc; };

const float kInfinity = 1e30;

void addStat(uint index, uint value) {
  uint total = subgroupAdd(value);
  if (subgroupElect() && total > 0u) atomicAdd(stats[index], total);
}

void main() {
  uvec2 pixel = gl_GlobalInvocationID.xy;
  bool inside = all(lessThan(pixel, frame.resolution));
  uint rays = 0u, shadowRays = 0u, vertices = 0u, emitterHit = 0u, invalid = 0u;
  vec3 radiance = vec3(0.0);

  if (inside) {
    uint sampleId = frame.frameIndex + pc.sampleIndex;
    Rng rng = rngSeed(pixel.y * frame.resolution.x + pixel.x, sampleId, frame.seed);
    vec2 jitter = rngNext2(rng);
    vec2 ndc = (vec2(pixel) + jitter) / vec2(frame.resolution) * 2.0 - 1.0;
    GpuCamera cam = frame.camera;
    vec3 dir = normalize(cam.forward + ndc.x * cam.tanHalfFovY * cam.aspect * cam.right -
                         ndc.y * cam.tanHalfFovY * cam.up);
    vec3 origin = cam.position;
    vec3 throughput = vec3(1.0);
    float prevBsdfPdf = 0.0;  // pdf of the direction that led here (0: camera ray)
    bool nee = (frame.flags & kFlagNee) != 0u && frame.lightCount > 0u;
    bool emitterHits = (frame.flags & kFlagEmitterHits) != 0u;
    bool mis = (frame.flags & kFlagMis) != 0u && nee && emitterHits;

    for (uint depth = 0u;; ++depth) {
      BvhHit hit;
      ++rays;
      if (!traceClosest(origin, dir, kInfinity, hit)) {
        // Only the sky fallback light lives at infinity.
        for (uint i = 0u; i < min(frame.lightCount, 1u); ++i) {
          uint last = frame.lightCount - 1u;
          if (lights[last].type != kLightSky) break;
          float w = 1.0;
          if (depth > 0u) {
            if (!emitterHits) w = 0.0;
            else if (mis) w = powerHeuristic(1.0, prevBsdfPdf, 1.0, skyLightPdf(lightSelectPdf(last, frame.lightCount)));
          }
          radiance += throughput * lights[last].emission * w;
          if (depth > 0u && w > 0.0) emitterHit = 1u;
        }
        break;
      }
      Surface s = resolveSurface(hit, origin, dir);
      vec3 le = surfaceEmission(s);
      if (le != vec3(0.0)) {
        float w = 1.0;
        if (depth > 0u) {
          if (!emitterHits) w = 0.0;
          else if (mis) {
            uint li = triangles[s.triangle].light;
            float lightPdf = li == kNoLight ? 0.0
                : triangleLightPdf(lights[li], lightSelectPdf(li, frame.lightCount), dir, hit.t * length(dir));
            w = powerHeuristic(1.0, prevBsdfPdf, 1.0, lightPdf);
          }
          emitterHit = 1u;
        }
        radiance += throughput * le * w;
      }
      if (depth >= frame.maxDepth) break;
      ++vertices;

      BsdfParams bsdf = surfaceBsdf(s);
      vec3 ns = s.shadingNormal;
      if (dot(ns, -dir) <= 0.0) ns = s.geometricNormal;  // shading normal faces away: fall back
      TangentFrame tf = frameFromNormal(ns);
      vec3 wo = localFromWorld(tf, -dir);
      vec3 p = offsetRayOrigin(s.position, s.geometricNormal);

      if (nee) {
        LightSample ls = sampleLight(s.position, rngNext3(rng), frame.lightCount);
        vec3 wi = localFromWorld(tf, ls.direction);
        if (ls.pdf > 0.0 && wi.z > 0.0 && dot(ls.direction, s.geometricNormal) > 0.0 &&
            ls.radiance != vec3(0.0)) {
          vec3 f = bsdfEval(bsdf, wo, wi) * wi.z;
          float w = ls.delta || !mis ? 1.0 : powerHeuristic(1.0, ls.pdf, 1.0, bsdfPdf(bsdf, wo, wi));
          vec3 contribution = throughput * f * ls.radiance * (w / ls.pdf);
          if (contribution != vec3(0.0)) {
            ++rays;
            ++shadowRays;
            float tMax = ls.distance >= kInfinity ? kInfinity : ls.distance * (1.0 - 1e-4);
            if (!traceAny(p, ls.direction, tMax)) radiance += contribution;
          }
        }
      }

      vec3 wiLocal;
      float pdf;
      if (!bsdfSample(bsdf, wo, rngNext3(rng), wiLocal, pdf)) break;
      vec3 wiWorld = worldFromLocal(tf, wiLocal);
      if (dot(wiWorld, s.geometricNormal) <= 0.0) break;  // would pass under the surface
      throughput *= bsdfEval(bsdf, wo, wiLocal) * (wiLocal.z / pdf);
      prevBsdfPdf = pdf;

      if ((frame.flags & kFlagRussianRoulette) != 0u && depth >= 2u) {
        float survive = min(max(throughput.r, max(throughput.g, throughput.b)), 0.95);
        if (rngNextFloat(rng) >= survive) break;
        throughput /= survive;
      }
      origin = p;
      dir = wiWorld;
    }
    if (any(isnan(radiance)) || any(isinf(radiance))) {
      radiance = vec3(0.0);
      invalid = 1u;
    }
    vec4 acc = imageLoad(uAccum, ivec2(pixel));
    imageStore(uAccum, ivec2(pixel), acc + vec4(radiance, 1.0));
  }
  addStat(kStatRays, rays);
  addStat(kStatShadowRays, shadowRays);
  addStat(kStatPaths, inside ? 1u : 0u);
  addStat(kStatEmitterHits, emitterHit);
  addStat(kStatPathVertices, vertices);
  addStat(kStatInvalidSamples, invalid);
}
