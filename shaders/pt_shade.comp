#version 460
// Wavefront pass 3: shades each path's hit at depth pc.bounce. Emission (MIS
// weighted), the vertex's cache point (found once: it completes the previous
// vertex's Q update and guides this one), NEE with learned light choice
// (its shadow ray is traced by the next trace pass), then the next direction
// from the guided/BSDF mixture, Russian roulette.
#extension GL_GOOGLE_include_directive : require
#include "include/path_common.glsl"
#include "include/path_queue.glsl"
layout(binding = QL_BIND_QUEUE_OUT, scalar) writeonly buffer QueueOut { uint queueOut[]; };

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
  uint path = queuedPath(gl_GlobalInvocationID.x);
  if (path == 0xffffffffu) return;
  if ((floatBitsToUint(pathTexel(path, 3u).w) & kPathAlive) == 0u) return;
  PathState st = loadPath(path);
  Rng rng;
  rng.state = st.rng;
  uint depth = pc.bounce;
  bool nee = (frame.flags & kFlagNee) != 0u && frame.lightCount > 0u;
  bool emitterHits = (frame.flags & kFlagEmitterHits) != 0u;
  bool mis = (frame.flags & kFlagMis) != 0u && nee && emitterHits;
  bool learn = (guiding.flags & kGuideLearn) != 0u;
  bool guide = (guiding.flags & kGuideSample) != 0u;
  bool usePoints = kUseGuiding && (learn || guide || (guiding.flags & (kGuideLightLearn | kGuideSpawn)) != 0u);
  bool alive = false;  // set when the path scatters on

  if (st.hitT < 0.0) {
    // Only the sky fallback light lives at infinity; it is the last light.
    float skyLuminance = 0.0;
    uint last = frame.lightCount - 1u;
    if (kUseNonTriangleLights && frame.lightCount > 0u && lights[last].type == kLightSky) {
      float w = 1.0;
      if (depth > 0u) {
        if (!emitterHits) w = 0.0;
        else if (mis) w = powerHeuristic(1.0, st.prevScatterPdf, 1.0, skyLightPdf(lightSelectionPdf(st.prevPoint, last)));
        st.flags |= kPathEmitterHit;
      }
      st.radiance += st.throughput * lights[last].emission * w;
      skyLuminance = luminance(lights[last].emission);
    }
    if (kUseGuiding && learn) recordQTarget(st.prevEntry, skyLuminance);
  } else {
    BvhHit hit;
    hit.t = st.hitT;
    hit.u = st.hitU;
    hit.v = st.hitV;
    hit.instance = st.hitInstance;
    hit.primitive = st.hitPrimitive;
    vec3 dir = st.dir;
    Surface s = resolveSurface(hit, st.origin, dir);
    vec3 le = surfaceEmission(s);
    if (le != vec3(0.0)) {
      float w = 1.0;
      if (depth > 0u) {
        if (!emitterHits) w = 0.0;
        else if (mis) {
          uint li = triangleAt(s.triangle).light;
          float lightPdf = li == kNoLight ? 0.0
              : triangleLightPdf(lights[li], lightSelectionPdf(st.prevPoint, li), dir, hit.t * length(dir));
          w = powerHeuristic(1.0, st.prevScatterPdf, 1.0, lightPdf);
        }
        st.flags |= kPathEmitterHit;
      }
      st.radiance += st.throughput * le * w;
    }

    BsdfParams bsdf = surfaceBsdf(s);
    vec3 ns = s.shadingNormal;
    if (dot(ns, -dir) <= 0.0) ns = s.geometricNormal;  // shading normal faces away: fall back
    TangentFrame tf = frameFromNormal(ns);
    vec3 wo = localFromWorld(tf, -dir);

    uint point = usePoints ? findCachePoint(s.position, s.geometricNormal) : kNoCachePoint;
    if (point != kNoCachePoint) {
      if (depth < frame.maxDepth) st.covered++;
      if (learn && st.prevEntry != kNoCachePoint)
        recordQTarget(st.prevEntry, luminance(le) + scatteredEstimate(point, bsdf, wo, -dir, ns));
    } else if (usePoints && depth == 0u && (guiding.flags & kGuideSpawn) != 0u) {
      reportUncovered(path, pc.pathCount, frame.frameIndex + pc.sampleIndex, s.position, s.geometricNormal);
    }

    if (depth < frame.maxDepth) {
      if ((st.flags & kPathEmitterHit) == 0u) st.vertices++;  // up to the first emitter reached (D&K)
      TangentFrame pf = point != kNoCachePoint ? pointFrame(point) : tf;
      float guideShare = kUseGuiding && guide && point != kNoCachePoint
          ? guiding.selectProbability * (1.0 - bsdfSpecularProbability(bsdf, wo)) * pointConfidence(point)
          : 0.0;
      vec3 p = offsetRayOrigin(s.position, s.geometricNormal);

      if (nee) {
        float selectPdf;
        uint li = chooseLight(point, rngNextFloat(rng), selectPdf);
        LightSample ls = sampleLight(s.position, rngNext2(rng), li, selectPdf);
        vec3 wi = localFromWorld(tf, ls.direction);
        bool valid = ls.pdf > 0.0 && wi.z > 0.0 && dot(ls.direction, s.geometricNormal) > 0.0 &&
                     ls.radiance != vec3(0.0);
        vec3 contribution = vec3(0.0);
        float target = 0.0;  // f cos L / pdf(point on light | light), if unoccluded
        if (valid) {
          vec3 f = bsdfEval(bsdf, wo, wi) * wi.z;
          target = luminance(f * ls.radiance * (selectPdf / ls.pdf));
          float scatterPdf = (1.0 - guideShare) * bsdfPdf(bsdf, wo, wi);
          if (guideShare > 0.0) scatterPdf += guideShare * guidedPdfWorld(point, pf, ls.direction);
          float w = ls.delta || !mis ? 1.0 : powerHeuristic(1.0, ls.pdf, 1.0, scatterPdf);
          contribution = st.throughput * f * ls.radiance * (w / ls.pdf);
        }
        bool learnLight = lightLearningOn(point);
        if (contribution != vec3(0.0)) {  // the next trace pass traces the shadow ray
          st.flags |= kPathShadowPending;
          st.shadowOrigin = p;
          st.shadowDir = ls.direction;
          st.shadowTMax = ls.distance >= kInfinity ? kInfinity : ls.distance * (1.0 - 1e-4);
          st.shadowContribution = contribution;
          st.shadowTarget = target;
          st.shadowPoint = learnLight ? point : kNoCachePoint;
          st.shadowLight = li;
        } else if (learnLight) {
          recordVTarget(point, li, 0.0);
        }
      }

      // Scatter: the learned distribution with probability guideShare, else the BSDF.
      vec3 wiWorld = vec3(0.0);
      bool sampled;
      if (rngNextFloat(rng) < guideShare) {
        vec3 local;
        float guidedPdfValue;
        sampled = sampleGuided(point * strataCount(), rngNext3(rng), guiding.rows, guiding.cols, local, guidedPdfValue);
        wiWorld = worldFromLocal(pf, local);
      } else {
        vec3 local;
        float bsdfPdfValue;
        sampled = bsdfSample(bsdf, wo, rngNext3(rng), local, bsdfPdfValue);
        wiWorld = worldFromLocal(tf, local);
      }
      vec3 wiLocal = localFromWorld(tf, wiWorld);
      float pdf = 0.0;
      if (sampled && wiLocal.z > 0.0 && dot(wiWorld, s.geometricNormal) > 0.0) {  // not under the surface
        pdf = (1.0 - guideShare) * bsdfPdf(bsdf, wo, wiLocal);
        if (guideShare > 0.0) pdf += guideShare * guidedPdfWorld(point, pf, wiWorld);
      }
      if (pdf > 0.0) {
        st.throughput *= bsdfEval(bsdf, wo, wiLocal) * (wiLocal.z / pdf);
        st.prevScatterPdf = pdf;
        st.prevPoint = point;
        st.prevEntry = learn && point != kNoCachePoint ? qEntry(point, pf, wiWorld) : kNoCachePoint;
        alive = true;
        if ((frame.flags & kFlagRussianRoulette) != 0u && depth >= 2u) {
          float survive = min(max(st.throughput.r, max(st.throughput.g, st.throughput.b)), 0.95);
          if (rngNextFloat(rng) >= survive) alive = false;
          else st.throughput /= survive;
        }
        st.origin = p;
        st.dir = wiWorld;
      }
    }
  }
  st.flags = alive ? (st.flags | kPathAlive) : (st.flags & ~kPathAlive);
  st.rng = rng.state;
  storePath(path, st);
  // Survivors, and paths that still have a shadow ray, go to the next trace.
  if ((st.flags & (kPathAlive | kPathShadowPending)) != 0u)
    queueOut[atomicAdd(queues[(pc.bounce + 1u) & 1u].count, 1u)] = path;
}
