#version 460
// Wavefront pass 3: shades each queued path's hit at depth pc.bounce, one step
// per function (main lists them): emission reached by the ray, the vertex's
// cache point, NEE (its shadow ray traced here), the next
// direction from the guided/BSDF mixture, Russian roulette, and the survivors
// queued for the next trace.
//
// On lavapipe both sides of every branch execute, so the kUse* guards
// (specialization constants, include/features.glsl) must stay where they are:
// they remove the code of the features a frame does not use. The same holds
// for the bounce: each phase (camera hits, bounce 1, later) has a pipeline of
// its own, and the steps of the others (atCameraHit, atRouletteBounce) are not in it.
#extension GL_GOOGLE_include_directive : require
#include "include/path_common.glsl"
#include "include/path_queue.glsl"
#include "include/learning_returns.glsl"
#include "include/camera_path.glsl"
layout(binding = QL_BIND_QUEUE_OUT, scalar) writeonly buffer QueueOut { uint queueOut[]; };

// The frame's estimator and guiding switches.
struct Switches {
  bool nee;          // sample a light at every vertex
  bool emitterHits;  // scattered rays that reach an emitter count
  bool mis;          // both, weighted by the power heuristic
  bool learn;        // record Q-learning targets
  bool returns;      // ... from returns (include/learning_returns.glsl)
  bool learnTd;      // ... else from D&K's one-step TD target
  bool guide;        // sample from the learned distributions
  bool usePoints;    // look up the vertex's cache point (for any of the above, or to spawn one)
  bool roulette;     // Russian roulette by the expected contribution Q predicts
};

Switches frameSwitches() {
  Switches sw;
  sw.nee = (frame.flags & kFlagNee) != 0u && frame.lightCount > 0u;
  sw.emitterHits = (frame.flags & kFlagEmitterHits) != 0u;
  sw.mis = (frame.flags & kFlagMis) != 0u && sw.nee && sw.emitterHits;
  sw.learn = kLearning && (guiding.flags & kGuideLearn) != 0u;
  sw.returns = learningFromReturns();
  sw.learnTd = kUseTdTarget && sw.learn && !sw.returns;
  sw.guide = (guiding.flags & kGuideSample) != 0u;
  sw.usePoints = kUseGuiding &&
                 (sw.learn || sw.guide || (guiding.flags & (kGuideLightLearn | kGuideSpawn)) != 0u);
  sw.roulette = kUseGuiding && sw.guide && (guiding.flags & kGuideRoulette) != 0u &&
                (frame.flags & kFlagRussianRoulette) != 0u;
  return sw;
}

// A hit as a scattering vertex.
struct Vertex {
  Surface s;
  BsdfParams bsdf;
  TangentFrame tf;  // shading frame
  vec3 ns;          // its normal
  vec3 wo;          // toward the previous vertex, in tf
};

// The vertex's direction mixture: the cache point's learned distribution with
// probability guideShare, else the BSDF.
struct ScatterMix {
  uint point;     // kNoCachePoint: BSDF only
  GuidedRow row;  // the point's frame (its strata) and CDF row
  float guideShare;
  float confidence;  // the point's (0: none)
};

// Light selection: by power, mixed with the learned V(point, light) when on; times p, the
// probability that the vertex samples a light at all (learned NEE, else 1).
float lightSelectionPdfWith(uint point, uint light, float p) {
  float power = lightSelectPdf(light, frame.lightCount);
  if (!lightLearningOn(point)) return p * power;
  return p * (guiding.lightMix * learnedLightProbability(point, light) +
              (1.0 - guiding.lightMix) * power);
}

float lightSelectionPdf(uint point, uint light) {
  return lightSelectionPdfWith(point, light, neeProbability(point));
}

// neeP: the point's neeProbability, read once per vertex.
uint chooseLight(uint point, float neeP, float u, out float selectPdf) {
  uint light;
  if (lightLearningOn(point)) {
    float beta = guiding.lightMix;
    float ignored;
    light = u < beta ? sampleLearnedLight(point, u / beta)
                     : selectLight((u - beta) / (1.0 - beta), frame.lightCount, ignored);
    selectPdf = lightSelectionPdfWith(point, light, neeP);
  } else {
    light = selectLight(u, frame.lightCount, selectPdf);
    selectPdf *= neeP;
  }
  return light;
}

// The ray left the scene: only the sky (environment map, uniform sky or the
// fallback) lives at infinity, as the last lights (one per tile of a map). Its
// luminance in the ray's direction completes the previous vertex's Q update.
void shadeEscaped(inout PathState st, Switches sw) {
  float skyLuminance = 0.0;
  uint last = frame.lightCount - 1u;
  if (kUseNonTriangleLights && frame.lightCount > 0u && lightAt(last).type == kLightSky) {
    SkySeen sky = skySeenFrom(last, st.dir);
    float w = 1.0;
    if (!atCameraHit()) {  // camera rays see the sky unweighted
      if (!sw.emitterHits) w = 0.0;
      else if (sw.mis) {
        float lightPdf = lightSelectionPdf(st.prevPoint, sky.light) * sky.pdf;
        w = powerHeuristic(1.0, st.prevScatterPdf, 1.0, lightPdf);
      }
      st.flags |= kPathEmitterHit;
    }
    st.radiance += st.throughput * sky.radiance * w;
    skyLuminance = luminance(sky.radiance);
  }
  if (kUseGuiding && sw.learnTd) recordQTarget(st.prevEntry, skyLuminance);
}

Surface hitSurface(PathState st) {
  BvhHit hit;
  hit.t = st.hitT;
  hit.u = st.hitU;
  hit.v = st.hitV;
  hit.instance = st.hitInstance;
  hit.primitive = st.hitPrimitive;
  return resolveSurfaceWithCone(hit, st.origin, st.dir,
                                st.coneWidth + st.coneSpread * st.hitT * length(st.dir));
}

// Emission at the hit; after the camera ray, MIS-weighted against NEE having
// chosen the same light at the previous vertex. Returns the unweighted value.
vec3 addEmission(inout PathState st, Surface s, Switches sw) {
  // Past the camera ray the emitter is read as NEE reads it, at its finest texels: MIS combines
  // two estimates of one emission only if both see the same texture (a cone's coarse level
  // would blur a glow map's light over the triangles around it).
  if (!atCameraHit()) s.textureLod = kFinestLod;
  vec3 le = surfaceEmission(s);
  if (le != vec3(0.0)) {
    float w = 1.0;
    if (!atCameraHit()) {
      uint li = triangleAt(s.triangle).light;
      // Emitters outside the light list (unlit surfaces) are found by scattered rays only.
      if (li == kNoLight) w = 1.0;
      else if (!sw.emitterHits) w = 0.0;
      else if (sw.mis) {
        float lightPdf = triangleLightPdf(lightAt(li), lightSelectionPdf(st.prevPoint, li), st.dir,
                                          st.hitT * length(st.dir));
        w = powerHeuristic(1.0, st.prevScatterPdf, 1.0, lightPdf);
      }
      st.flags |= kPathEmitterHit;
    }
    st.radiance += st.throughput * le * w;
  }
  return le;
}

Vertex scatteringVertex(Surface s, vec3 dir) {
  Vertex v;
  v.s = s;
  v.bsdf = surfaceBsdf(s);
  v.ns = s.shadingNormal;
  if (dot(v.ns, -dir) <= 0.0) v.ns = s.geometricNormal;  // shading normal faces away: fall back
  v.tf = frameFromNormal(v.ns);
  v.wo = localFromWorld(v.tf, -dir);
  return v;
}

// The vertex's cache point, found once: it completes the previous vertex's Q
// update (emission plus the radiance Q says the vertex scatters, D&K eq. 5)
// and guides this one. Camera hits that no point covers are reported as
// candidates for new points.
uint lookupCachePoint(inout PathState st, uint path, Vertex v, vec3 le, Switches sw) {
  uint point = sw.usePoints ? findCachePoint(v.s.position, v.s.geometricNormal) : kNoCachePoint;
  if (point != kNoCachePoint) {
    if (pc.bounce < frame.maxDepth) st.covered++;
    if (sw.learnTd && st.prevEntry != kNoCachePoint)
      recordQTarget(st.prevEntry,
                    luminance(le) + scatteredEstimate(point, v.bsdf, v.wo, -st.dir, v.ns));
  } else if (sw.usePoints && atCameraHit() && (guiding.flags & kGuideSpawn) != 0u) {
    reportUncovered(path, pc.pathCount, frame.frameIndex + pc.sampleIndex, v.s.position,
                    v.s.geometricNormal);
  }
  return point;
}

// A point guides at a share that shrinks with the BSDF's specular and
// transmitted parts (which the strata cannot resolve) and with too few updates for its Q to be trusted.
ScatterMix scatterMix(uint point, Vertex v, Switches sw) {
  ScatterMix m;
  m.point = point;
  if (kUseDqn) {
    m.row = dqnRow(v.s.position, v.s.geometricNormal);
  } else if (point != kNoCachePoint) {
    m.row = guidedRow(point);
  } else {
    m.row.frame = v.tf;
    m.row.base = 0u;
    m.row.total = 1.0;
  }
  m.confidence = kUseGuiding && point != kNoCachePoint ? pointConfidence(point) : 0.0;
  m.guideShare = kUseGuiding && sw.guide
                     ? guiding.selectProbability * bsdfDiffuseProbability(v.bsdf, v.wo) *
                           m.confidence
                     : 0.0;
  return m;
}

// The density with which the mixture produces direction wi, whichever
// technique did: MIS and the throughput need it. g is wi's guided lookup at the point.
float mixturePdfOf(ScatterMix m, Vertex v, vec3 wiLocal, GuidedLookup g) {
  float pdf = (1.0 - m.guideShare) * bsdfPdf(v.bsdf, v.wo, wiLocal);
  if (m.guideShare > 0.0) pdf += m.guideShare * g.pdf;
  return pdf;
}

float mixturePdf(ScatterMix m, Vertex v, vec3 wiLocal, vec3 wiWorld) {
  GuidedLookup g;
  g.pdf = 0.0;
  if (m.guideShare > 0.0) g = guidedLookup(m.row, localFromWorld(m.row.frame, wiWorld));
  return mixturePdfOf(m, v, wiLocal, g);
}

// A direction the vertex can scatter into: above both the shading and the
// geometric surface, or below both where the material transmits.
bool scatterable(Vertex v, vec3 wiLocal, vec3 wiWorld) {
  float side = dot(wiWorld, v.s.geometricNormal);
  return (wiLocal.z > 0.0 && side > 0.0) ||
         (v.bsdf.transmission > 0.0 && wiLocal.z < 0.0 && side < 0.0);
}

// Ray origins just off the surface on each side (above: the side of the incoming ray).
struct RayOrigins {
  vec3 above, below;
};

vec3 originToward(RayOrigins o, Vertex v, vec3 dir) {
  return dot(dir, v.s.geometricNormal) > 0.0 ? o.above : o.below;
}

// NEE: one light sample, MIS-weighted against the scatter mixture, and its
// shadow ray traced here (the path state keeps no shadow ray: each texel it
// stores costs, on lavapipe, more than the ray's traversal adds to this pass);
// with light learning, the light's value target is recorded: 0 when occluded
// or when there is no ray.
// With learned NEE the vertex samples a light with its point's probability only (the
// selection pdf carries it). The coin is shared by kNeeCoinGroup paths of neighbouring ids
// (neighbours in the queue too: it keeps their order): a shadow ray costs its whole SIMD
// group, so the skips only pay when the group skips together. Each path still skips with
// its own probability (unbiased); only which ones skip together is correlated. By path id,
// not queue slot, so the same seed gives the same image.
const uint kNeeCoinGroup = 32u;  // a subgroup on most GPUs, 4 of lavapipe's 8-wide ones

float neeCoin(uint path) {
  uint group = path / kNeeCoinGroup;
  return uintToUnitFloat(pcgHash(pcgHash(group ^ (frame.frameIndex * 9781u)) ^
                                 (pc.sampleIndex * 6271u + pc.bounce * 1013u + frame.seed)));
}

void sampleDirectLight(inout PathState st, inout Rng rng, uint path, Vertex v, ScatterMix m,
                       RayOrigins o, bool mis) {
  float neeP = neeProbability(m.point);
  if (neeP < 1.0 && neeCoin(path) >= neeP) return;
  float selectPdf;
  uint li = chooseLight(m.point, neeP, rngNextFloat(rng), selectPdf);
  LightSample ls = sampleLight(v.s.position, rngNext2(rng), li, selectPdf);
  vec3 wi = localFromWorld(v.tf, ls.direction);
  bool valid = ls.pdf > 0.0 && scatterable(v, wi, ls.direction) && ls.radiance != vec3(0.0);
  vec3 contribution = vec3(0.0);
  float target = 0.0;  // f cos L / pdf(point on light | light), if unoccluded
  if (valid) {
    vec3 f = bsdfEval(v.bsdf, v.wo, wi) * abs(wi.z);
    target = luminance(f * ls.radiance * (selectPdf / ls.pdf));
    float scatterPdf = mixturePdf(m, v, wi, ls.direction);
    float w = ls.delta || !mis ? 1.0 : powerHeuristic(1.0, ls.pdf, 1.0, scatterPdf);
    contribution = st.throughput * f * ls.radiance * (w / ls.pdf);
  }
  bool unoccluded = false;
  if (contribution != vec3(0.0)) {
    st.rays++;
    st.shadowRays++;
    float tMax = ls.distance >= kInfinity ? kInfinity : ls.distance * (1.0 - 1e-4);
    unoccluded = !traceAny(originToward(o, v, ls.direction), ls.direction, tMax);
    if (unoccluded) st.radiance += contribution;
    recordShadowRay(m.point, unoccluded);
  }
  if (kLearning && lightLearningOn(m.point)) recordVTarget(m.point, li, unoccluded ? target : 0.0);
}

// Radians a diffuse bounce adds to a ray cone's spread (a wide lobe: coarse texture levels).
const float kDiffuseConeSpread = 0.25;

// The next direction from the mixture, and the path moved onto it. Returns
// false when no usable direction came out (the path ends).
// expectedLi: Q in the direction taken (< 0: unknown).
bool sampleScatter(inout PathState st, inout Rng rng, Vertex v, ScatterMix m, RayOrigins o,
                   bool learn, bool roulette, out float expectedLi) {
  vec3 wiWorld = vec3(0.0);
  vec3 pointLocal = vec3(0.0);  // wi in the point's frame
  GuidedLookup g;               // and its entry and guided pdf: found once, for the pdf and learning
  g.entry = kNoCachePoint;
  g.pdf = 0.0;
  bool guided = rngNextFloat(rng) < m.guideShare;
  bool sampled = true;
  if (guided) {
    g = drawGuidedDirection(m.row, rngNext3(rng), pointLocal);
    wiWorld = worldFromLocal(m.row.frame, pointLocal);
  } else {
    vec3 local;
    float bsdfPdfValue;
    sampled = bsdfSample(v.bsdf, v.wo, rngNext3(rng), local, bsdfPdfValue);
    wiWorld = worldFromLocal(v.tf, local);
    pointLocal = localFromWorld(m.row.frame, wiWorld);
  }
  if (m.point != kNoCachePoint && (m.guideShare > 0.0 || learn || roulette))
    g = guidedLookupAt(m.row, pointLocal, g);
  expectedLi = m.point != kNoCachePoint ? lookedUpQ(m.row, g, pointLocal.z) : -1.0;
  if (guided) sampled = pointLocal.z > 0.0 && g.pdf > 0.0;
  vec3 wiLocal = localFromWorld(v.tf, wiWorld);
  float pdf = 0.0;
  // Directions between the shading and the geometric surface are lost.
  if (sampled && scatterable(v, wiLocal, wiWorld)) pdf = mixturePdfOf(m, v, wiLocal, g);
  bool moved = pdf > 0.0;
  if (moved) {
    st.throughput *= bsdfEval(v.bsdf, v.wo, wiLocal) * (abs(wiLocal.z) / pdf);
    st.prevScatterPdf = pdf;
    st.prevPoint = m.point;
    // The Q entry this direction updates once the next vertex is known.
    st.prevEntry = learn && m.point != kNoCachePoint && pointLocal.z > 0.0 ? g.entry : kNoCachePoint;
    if (kUseDqn && st.prevEntry != kNoCachePoint)  // the entry is the row's stratum
      st.prevEntry = dqnOpenRecord(v.s.position, m.row.frame.normal, st.prevEntry - m.row.base);
    // The ray cone after the bounce: its width here, spread by the lobe (a diffuse bounce
    // blurs what the next hit reads from its textures, a glossy one by its roughness).
    st.coneWidth += st.coneSpread * st.hitT * length(st.dir);
    float glossy = (1.0 - bsdfDiffuseProbability(v.bsdf, v.wo)) * (1.0 - m.guideShare);
    st.coneSpread += mix(kDiffuseConeSpread, 2.0 * ggxAlpha(v.bsdf.roughness), glossy);
    st.origin = originToward(o, v, wiWorld);
    st.dir = wiWorld;
  }
  return moved;
}

// From depth 2 on, a path survives with probability ~ its throughput, or
// guided, ~ its expected contribution (guidedSurvivalProbability); survivors
// are reweighted, so the estimate stays unbiased.
float expectedRadianceAtFirstVertex(uint path) {
  return pathTexel(path, kPathTexelRouletteScale).x;
}

bool survivesRoulette(inout PathState st, inout Rng rng, uint path, Switches sw, ScatterMix m,
                      float expectedLi) {
  if ((frame.flags & kFlagRussianRoulette) == 0u || !atRouletteBounce()) return true;
  float survive = min(max(st.throughput.r, max(st.throughput.g, st.throughput.b)),
                      kRouletteMaxSurvival);
  if (sw.roulette && expectedLi >= 0.0) {
    float firstVertex = expectedRadianceAtFirstVertex(path);
    if (firstVertex > 0.0)
      survive = guidedSurvivalProbability(survive, luminance(st.throughput) * expectedLi,
                                          firstVertex, m.confidence);
  }
  if (rngNextFloat(rng) >= survive) return false;
  st.throughput /= survive;
  return true;
}

// Survivors go to the next trace.
void enqueueSurvivor(uint path, uint flags) {
  if ((flags & kPathAlive) != 0u)
    queueOut[atomicAdd(queues[(pc.bounce + 1u) & 1u].count, 1u)] = path;
}

// The hit as a scattering vertex: its cache point, NEE and the next direction.
// Returns whether the path goes on.
bool scatterAt(inout PathState st, inout Rng rng, uint path, Surface s, vec3 le, Switches sw) {
  Vertex v = scatteringVertex(s, st.dir);
  uint point = lookupCachePoint(st, path, v, le, sw);
  if (pc.bounce >= frame.maxDepth) return false;
  // D&K's path length: vertices up to the first emitter reached.
  if ((st.flags & kPathEmitterHit) == 0u) st.vertices++;
  ScatterMix m = scatterMix(point, v, sw);
  RayOrigins o;
  o.above = offsetRayOriginFrom(s.position, s.geometricNormal, s.extent);
  o.below = offsetRayOriginFrom(s.position, -s.geometricNormal, s.extent);
  if (sw.roulette && atCameraHit()) {
    float scale = m.point != kNoCachePoint && m.confidence > 0.0
                      ? rowScatteredEstimate(m.row, v.bsdf, v.wo, -st.dir, v.ns)
                      : 0.0;
    setPathTexel(path, kPathTexelRouletteScale, vec4(scale, 0.0, 0.0, 0.0));
  }
  if (sw.nee) sampleDirectLight(st, rng, path, v, m, o, sw.mis);
  float expectedLi;
  bool alive = sampleScatter(st, rng, v, m, o, sw.learn, sw.roulette, expectedLi);
  if (alive) alive = survivesRoulette(st, rng, path, sw, m, expectedLi);
  if (alive) st.rays++;  // the next trace pass traces its ray
  return alive;
}

// Fused, the camera-hit pipeline starts every pixel's path itself (no begin pass, no queue
// 0 to read): slot i is path i.
bool startsCameraPaths() { return kTraceInShade && kBouncePhase == kBouncePhaseCamera; }

void main() {
  uint path;
  if (startsCameraPaths())
    path = gl_GlobalInvocationID.x < pc.pathCount ? gl_GlobalInvocationID.x : kNoPath;
  else
    path = queuedPath(gl_GlobalInvocationID.x);
  if (path == kNoPath) return;
  PathState st = startsCameraPaths() ? cameraPath(path) : loadPath(path);
  if (kTraceInShade) {
    BvhHit hit;
    bool found = traceClosest(st.origin, st.dir, kInfinity, hit);
    st.hitT = found ? hit.t : -1.0;
    st.hitU = hit.u;
    st.hitV = hit.v;
    st.hitInstance = hit.instance;
    st.hitPrimitive = hit.primitive;
  }
  Rng rng;
  rng.state = st.rng;
  Switches sw = frameSwitches();
  if (sw.returns && !atCameraHit()) openReturnRecord(st, path, pc.bounce);
  bool alive = false;
  if (st.hitT < 0.0) {
    shadeEscaped(st, sw);
  } else {
    Surface s = hitSurface(st);
    vec3 le = addEmission(st, s, sw);
    if (materialUnlit(materialAt(s.material))) {
      // KHR_materials_unlit: emission only, nothing scatters; the path ends.
      if (kUseGuiding && sw.learnTd) recordQTarget(st.prevEntry, luminance(le));
    } else {
      alive = scatterAt(st, rng, path, s, le, sw);
    }
  }
  st.flags = alive ? (st.flags | kPathAlive) : (st.flags & ~kPathAlive);
  st.rng = rng.state;
  storePath(path, st);
  enqueueSurvivor(path, st.flags);
}
