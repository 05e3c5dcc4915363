#version 460
// One sample per pixel of a unidirectional path tracer: BVH traversal in texel
// buffers, the glTF metallic-roughness BSDF, next event estimation combined with
// scattering by the power heuristic, Russian roulette, and Q-learned importance
// sampling: each vertex finds its cache point once, feeds the Q-learning target
// of the direction that led to it, and samples its next direction from a
// mixture of the learned distribution and the BSDF. Adds the sample to the
// accumulation image (rgb: sum of radiance, a: sample count).
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

layout(local_size_x = 64) in;
layout(binding = QL_BIND_FRAME, scalar) readonly buffer Frame { FrameUniforms frame; };
layout(binding = QL_BIND_ACCUM, rgba32f) uniform image2D uAccum;
layout(binding = QL_BIND_STATS) buffer Stats { uint stats[]; };
layout(push_constant, scalar) uniform Push { TracePush pc; };

const float kInfinity = 1e30;

void addStat(uint index, uint value) {
  uint total = subgroupAdd(value);
  if (subgroupElect() && total > 0u) atomicAdd(stats[index], total);
}

// Light selection: by power, mixed with the learned V(point, light) when on.
float lightSelectionPdf(uint point, uint light) {
  float power = lightSelectPdf(light, frame.lightCount);
  if (!lightLearningOn(point)) return power;
  return guiding.lightMix * learnedLightProbability(point, light) + (1.0 - guiding.lightMix) * power;
}

uint chooseLight(uint point, float u, out float selectPdf) {
  uint light;
  if (lightLearningOn(point)) {
    float beta = guiding.lightMix;
    float ignored;
    light = u < beta ? sampleLearnedLight(point, u / beta)
                     : selectLight((u - beta) / (1.0 - beta), frame.lightCount, ignored);
    selectPdf = lightSelectionPdf(point, light);
  } else {
    light = selectLight(u, frame.lightCount, selectPdf);
  }
  return light;
}

void main() {
  uvec2 pixel = uvec2(gl_GlobalInvocationID.x % frame.resolution.x, gl_GlobalInvocationID.x / frame.resolution.x);
  bool inside = gl_GlobalInvocationID.x < frame.resolution.x * frame.resolution.y;
  uint rays = 0u, shadowRays = 0u, vertices = 0u, emitterHit = 0u, invalid = 0u, covered = 0u;
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
    float prevScatterPdf = 0.0;        // pdf of the direction that led here (0: camera ray)
    uint prevPoint = kNoCachePoint;    // cache point of the previous vertex
    uint prevEntry = kNoCachePoint;    // its Q entry for the direction taken
    bool nee = (frame.flags & kFlagNee) != 0u && frame.lightCount > 0u;
    bool emitterHits = (frame.flags & kFlagEmitterHits) != 0u;
    bool mis = (frame.flags & kFlagMis) != 0u && nee && emitterHits;
    bool learn = (guiding.flags & kGuideLearn) != 0u;
    bool guide = (guiding.flags & kGuideSample) != 0u;
    bool usePoints = guiding.pointCount > 0u && (learn || guide || (guiding.flags & kGuideLightLearn) != 0u);

    for (uint depth = 0u;; ++depth) {
      BvhHit hit;
      ++rays;
      if (!traceClosest(origin, dir, kInfinity, hit)) {
        // Only the sky fallback light lives at infinity; it is the last light.
        float skyLuminance = 0.0;
        uint last = frame.lightCount - 1u;
        if (frame.lightCount > 0u && lights[last].type == kLightSky) {
          float w = 1.0;
          if (depth > 0u) {
            if (!emitterHits) w = 0.0;
            else if (mis) w = powerHeuristic(1.0, prevScatterPdf, 1.0, skyLightPdf(lightSelectionPdf(prevPoint, last)));
            emitterHit = 1u;
          }
          radiance += throughput * lights[last].emission * w;
          skyLuminance = luminance(lights[last].emission);
        }
        if (learn) recordQTarget(prevEntry, skyLuminance);
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
                : triangleLightPdf(lights[li], lightSelectionPdf(prevPoint, li), dir, hit.t * length(dir));
            w = powerHeuristic(1.0, prevScatterPdf, 1.0, lightPdf);
          }
          emitterHit = 1u;
        }
        radiance += throughput * le * w;
      }

      BsdfParams bsdf = surfaceBsdf(s);
      vec3 ns = s.shadingNormal;
      if (dot(ns, -dir) <= 0.0) ns = s.geometricNormal;  // shading normal faces away: fall back
      TangentFrame tf = frameFromNormal(ns);
      vec3 wo = localFromWorld(tf, -dir);

      // The vertex's cache point, found once: it completes the previous
      // vertex's Q update and guides this vertex's light choice and scattering.
      uint point = usePoints ? findCachePoint(s.position, s.geometricNormal) : kNoCachePoint;
      if (point != kNoCachePoint) {
        if (depth < frame.maxDepth) covered++;
        if (learn && prevEntry != kNoCachePoint)
          recordQTarget(prevEntry, luminance(le) + scatteredEstimate(point, bsdf, wo, -dir, ns));
      } else if (depth == 0u && (guiding.flags & kGuideSpawn) != 0u && rngNextFloat(rng) < 0.125) {
        reportUncovered(s.position, s.geometricNormal);
      }
      if (depth >= frame.maxDepth) break;
      if (emitterHit == 0u) ++vertices;  // path length up to the first emitter reached (D&K)

      TangentFrame pf = point != kNoCachePoint ? pointFrame(point) : tf;
      float guideShare = guide && point != kNoCachePoint
          ? guiding.selectProbability * (1.0 - bsdfSpecularProbability(bsdf, wo)) : 0.0;
      vec3 p = offsetRayOrigin(s.position, s.geometricNormal);

      if (nee) {
        float selectPdf;
        uint li = chooseLight(point, rngNextFloat(rng), selectPdf);
        LightSample ls = sampleLight(s.position, rngNext2(rng), li, selectPdf);
        vec3 wi = localFromWorld(tf, ls.direction);
        bool valid = ls.pdf > 0.0 && wi.z > 0.0 && dot(ls.direction, s.geometricNormal) > 0.0 &&
                     ls.radiance != vec3(0.0);
        vec3 unweighted = vec3(0.0);  // f cos L / pdf(point on light | light)
        if (valid) {
          vec3 f = bsdfEval(bsdf, wo, wi) * wi.z;
          unweighted = f * ls.radiance * (selectPdf / ls.pdf);
          float scatterPdf = (1.0 - guideShare) * bsdfPdf(bsdf, wo, wi);
          if (guideShare > 0.0) scatterPdf += guideShare * guidedPdfWorld(point, pf, ls.direction);
          float w = ls.delta || !mis ? 1.0 : powerHeuristic(1.0, ls.pdf, 1.0, scatterPdf);
          vec3 contribution = throughput * f * ls.radiance * (w / ls.pdf);
          if (contribution != vec3(0.0)) {
            ++rays;
            ++shadowRays;
            float tMax = ls.distance >= kInfinity ? kInfinity : ls.distance * (1.0 - 1e-4);
            if (!traceAny(p, ls.direction, tMax)) radiance += contribution;
            else unweighted = vec3(0.0);
          }
        }
        if (lightLearningOn(point)) recordVTarget(point, li, luminance(unweighted));
      }

      // Scatter: the learned distribution with probability guideShare, else the BSDF.
      vec3 wiWorld;
      if (rngNextFloat(rng) < guideShare) {
        vec3 local;
        float guidedPdfValue;
        if (!sampleGuided(point * strataCount(), rngNext3(rng), guiding.rows, guiding.cols, local, guidedPdfValue)) break;
        wiWorld = worldFromLocal(pf, local);
      } else {
        vec3 local;
        float bsdfPdfValue;
        if (!bsdfSample(bsdf, wo, rngNext3(rng), local, bsdfPdfValue)) break;
        wiWorld = worldFromLocal(tf, local);
      }
      vec3 wiLocal = localFromWorld(tf, wiWorld);
      if (wiLocal.z <= 0.0 || dot(wiWorld, s.geometricNormal) <= 0.0) break;  // under the surface
      float pdf = (1.0 - guideShare) * bsdfPdf(bsdf, wo, wiLocal);
      if (guideShare > 0.0) pdf += guideShare * guidedPdfWorld(point, pf, wiWorld);
      if (!(pdf > 0.0)) break;
      throughput *= bsdfEval(bsdf, wo, wiLocal) * (wiLocal.z / pdf);
      prevScatterPdf = pdf;
      prevPoint = point;
      prevEntry = learn && point != kNoCachePoint ? qEntry(point, pf, wiWorld) : kNoCachePoint;

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
  addStat(kStatCoveredVertices, covered);
}
