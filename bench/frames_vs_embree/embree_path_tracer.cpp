#include "bench/frames_vs_embree/embree_path_tracer.h"

#include <pmmintrin.h>
#include <xmmintrin.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <thread>

#include "engine/render/scene_packing.h"
#include "shaders/shared/random.h"
#include "shaders/shared/ray_offset.h"
#include "shaders/shared/sampling.h"

namespace qlight::bench {

using glm::vec3;
using shared::BsdfParams;

namespace {

constexpr uint32_t kNoLight = 0xffffffffu;
constexpr float kInfinity = 1e30f;
constexpr float kRouletteMaxSurvival = 0.95f;  // qlight's (shaders/shared/guiding_types.h)
constexpr float kPi = 3.14159265358979f;

void setRay(RTCRay& r, vec3 origin, vec3 dir, float tMax) {
  r.org_x = origin.x;
  r.org_y = origin.y;
  r.org_z = origin.z;
  r.tnear = 0.0f;
  r.dir_x = dir.x;
  r.dir_y = dir.y;
  r.dir_z = dir.z;
  r.time = 0.0f;
  r.tfar = tMax;
  r.mask = 0xffffffffu;
  r.id = 0;
  r.flags = 0;
}

BsdfParams bsdfOf(const scene::MaterialAsset& m) {
  BsdfParams p;
  p.baseColor = vec3(m.baseColorFactor);
  p.metallic = m.metallicFactor;
  p.roughness = m.roughnessFactor;
  p.specular = m.specularFactor;
  p.transmission = m.transmissionFactor;
  p.ior = m.ior;
  p.eta = 0.0f;  // thin-walled: the generated scenes have no volumes
  return p;
}

float maxAbs(vec3 v) { return std::max(std::abs(v.x), std::max(std::abs(v.y), std::abs(v.z))); }

}  // namespace

struct EmbreePathTracer::Surface {
  vec3 position;
  vec3 front;    // unit geometric normal of the winding's front side
  vec3 shading;  // the interpolated vertex normal in world space (front when the mesh has none)
  float extent = 0;
  const scene::MaterialAsset* material = nullptr;
  uint32_t materialIndex = 0;
  uint32_t light = kNoLight;
};

struct EmbreePathTracer::Counters {
  uint64_t rays = 0, shadowRays = 0;
};

EmbreePathTracer::EmbreePathTracer(const WorldScene& scene, RTCScene rtc)
    : scene_(scene), rtc_(rtc) {
  for (const scene::MaterialAsset& m : scene.asset.materials) {
    materialBsdf_.push_back(bsdfOf(m));
    materialLambertian_.push_back(render::exactlyLambertian(m));
  }
  float running = 0.0f;
  for (uint32_t i = 0; i < scene.instances.size(); ++i) {
    const WorldInstance& inst = scene.instances[i];
    const scene::MeshAsset& mesh = scene.asset.meshes[inst.mesh];
    glm::mat3 linear(scene.draws[i].worldFromObject);
    bool mirrored = glm::determinant(linear) < 0.0f;
    instanceNormalMatrix_.push_back(glm::transpose(glm::inverse(linear)));
    instanceFrontSign_.push_back(mirrored ? -1.0f : 1.0f);
    instanceFirstTriangle_.push_back(uint32_t(lightOfTriangle_.size()));
    for (uint32_t t = 0; t < mesh.triangleCount(); ++t) {
      const scene::MaterialAsset& m = scene.asset.materials[mesh.triangleMaterials[t]];
      lightOfTriangle_.push_back(kNoLight);
      if (!m.isEmissive()) continue;
      WorldTriangle w = scene.triangle(i, t);
      Light l;
      l.p0 = w.p0;
      l.edge1 = w.p1 - w.p0;
      l.edge2 = w.p2 - w.p0;
      vec3 n = glm::cross(l.edge1, l.edge2);
      l.area = 0.5f * glm::length(n);
      if (!(l.area > 0.0f)) continue;
      l.front = instanceFrontSign_.back() * n / (2.0f * l.area);
      l.emission = m.emissive;
      l.doubleSided = m.doubleSided;
      // qlight's selection weight: the emitted power.
      float power = shared::luminance(l.emission) * l.area * kPi * (l.doubleSided ? 2.0f : 1.0f);
      if (!(power > 0.0f)) continue;
      lightOfTriangle_.back() = uint32_t(lights_.size());
      lights_.push_back(l);
      lightCdf_.push_back(running += power);
    }
  }
  if (lights_.empty())
    throw std::runtime_error(
        scene.name + ": the Embree path tracer needs emissive triangles to light the scene");
}

float EmbreePathTracer::selectPdf(uint32_t light) const {
  float below = light > 0 ? lightCdf_[light - 1] : 0.0f;
  return (lightCdf_[light] - below) / lightCdf_.back();
}

uint32_t EmbreePathTracer::selectLight(float u) const {
  size_t k = std::upper_bound(lightCdf_.begin(), lightCdf_.end(), u * lightCdf_.back()) -
             lightCdf_.begin();
  return uint32_t(std::min(k, lightCdf_.size() - 1));
}

EmbreePathTracer::Surface EmbreePathTracer::surfaceAt(const RTCRayHit& rh) const {
  uint32_t instance = rh.hit.geomID, primitive = rh.hit.primID;
  WorldTriangle w = scene_.triangle(instance, primitive);
  Surface s;
  float u = rh.hit.u, v = rh.hit.v;
  s.position = (1.0f - u - v) * w.p0 + u * w.p1 + v * w.p2;
  vec3 n = glm::cross(w.p1 - w.p0, w.p2 - w.p0);
  s.front = instanceFrontSign_[instance] * glm::normalize(n);
  s.extent = std::max(maxAbs(w.p0), std::max(maxAbs(w.p1), maxAbs(w.p2)));
  const scene::MeshAsset& mesh = scene_.asset.meshes[scene_.instances[instance].mesh];
  s.shading = s.front;
  if (mesh.normals.size() == mesh.positions.size()) {
    const uint32_t* idx = &mesh.indices[3 * primitive];
    vec3 ns =
        instanceNormalMatrix_[instance] * ((1.0f - u - v) * mesh.normals[idx[0]] +
                                           u * mesh.normals[idx[1]] + v * mesh.normals[idx[2]]);
    float len = glm::length(ns);
    if (len > 1e-8f && std::isfinite(len)) s.shading = ns / len;
  }
  s.materialIndex = mesh.triangleMaterials[primitive];
  s.material = &scene_.asset.materials[s.materialIndex];
  s.light = lightOfTriangle_[instanceFirstTriangle_[instance] + primitive];
  return s;
}

vec3 EmbreePathTracer::samplePixel(uint32_t pixel, uint32_t sample, const PathTraceSettings& st,
                                   const CameraBasis& camera, Counters& counts) const {
  shared::Rng rng = shared::rngSeed(pixel, sample, st.seed);
  glm::vec2 xy(pixel % st.width, pixel / st.width);
  glm::vec2 ndc = (xy + shared::rngNext2(rng)) / glm::vec2(st.width, st.height) * 2.0f - 1.0f;
  vec3 dir = glm::normalize(camera.forward + ndc.x * camera.right - ndc.y * camera.up);
  vec3 origin = scene_.camera.position;

  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  vec3 radiance(0.0f), throughput(1.0f);
  float prevPdf = 0.0f;  // solid-angle pdf of the direction just taken (0: the camera's)
  for (uint32_t bounce = 0;; ++bounce) {
    RTCRayHit rh;
    setRay(rh.ray, origin, dir, kInfinity);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(rtc_, &ctx, &rh);
    counts.rays++;
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) break;  // no sky: emitters light the scene
    Surface s = surfaceAt(rh);
    vec3 wo = -dir;
    // Emission reached by this ray, MIS-weighted against NEE past the camera ray.
    if (s.material->isEmissive() && (s.material->doubleSided || glm::dot(s.front, wo) > 0.0f)) {
      float w = 1.0f;
      if (bounce > 0 && s.light != kNoLight) {
        const Light& l = lights_[s.light];
        float cosLight = std::abs(glm::dot(l.front, dir));
        float dist = rh.ray.tfar;
        float lightPdf =
            cosLight > 0.0f ? selectPdf(s.light) * dist * dist / (l.area * cosLight) : 0.0f;
        w = shared::powerHeuristic(1.0f, prevPdf, 1.0f, lightPdf);
      }
      radiance += throughput * s.material->emissive * w;
    }
    if (bounce >= st.maxDepth || s.material->unlit) break;
    // qlight's frame: the geometric normal facing the ray, the shading normal on its side
    // (the geometric one where the shading normal faces away from the ray).
    vec3 ng = glm::dot(s.front, wo) >= 0.0f ? s.front : -s.front;
    vec3 ns = glm::dot(s.shading, ng) >= 0.0f ? s.shading : -s.shading;
    if (glm::dot(ns, wo) <= 0.0f) ns = ng;
    shared::TangentFrame tf = shared::frameFromNormal(ns);
    vec3 woLocal = shared::localFromWorld(tf, wo);
    const BsdfParams& bsdf = materialBsdf_[s.materialIndex];
    const bool lambertian = materialLambertian_[s.materialIndex];
    vec3 above = shared::offsetRayOriginFrom(s.position, ng, s.extent);
    // Directions between the shading and the geometric surface are lost (as in qlight).
    auto scatterable = [&](vec3 wiLocal, vec3 wi) {
      return wiLocal.z > 0.0f && glm::dot(wi, ng) > 0.0f;
    };

    // NEE: a light by power, a point on it uniformly, one shadow ray.
    {
      uint32_t li = selectLight(shared::rngNextFloat(rng));
      const Light& l = lights_[li];
      vec3 bary = shared::sampleTriangleBarycentrics(shared::rngNext2(rng));
      vec3 p = l.p0 + bary.y * l.edge1 + bary.z * l.edge2;
      vec3 d = p - s.position;
      float dist = glm::length(d);
      if (dist > 0.0f) {
        vec3 wi = d / dist;
        float cosLight = glm::dot(l.front, -wi);
        vec3 wiLocal = shared::localFromWorld(tf, wi);
        if ((cosLight > 0.0f || l.doubleSided) && scatterable(wiLocal, wi)) {
          float lightPdf = selectPdf(li) * dist * dist / (l.area * std::abs(cosLight));
          vec3 f = lambertian ? bsdf.baseColor * (wiLocal.z / kPi)
                              : shared::bsdfEval(bsdf, woLocal, wiLocal) * wiLocal.z;
          float bsdfPdf = lambertian ? shared::cosineHemispherePdf(wiLocal.z)
                                     : shared::bsdfPdf(bsdf, woLocal, wiLocal);
          float w = shared::powerHeuristic(1.0f, lightPdf, 1.0f, bsdfPdf);
          vec3 contribution = throughput * f * l.emission * (w / lightPdf);
          if (contribution != vec3(0.0f)) {
            RTCRay shadow;
            setRay(shadow, above, wi, dist * (1.0f - 1e-4f));
            rtcOccluded1(rtc_, &ctx, &shadow);
            counts.rays++;
            counts.shadowRays++;
            if (shadow.tfar >= 0.0f) radiance += contribution;  // tfar = -inf: occluded
          }
        }
      }
    }

    // The next direction from the BSDF (a Lambertian one without qlight's general model).
    vec3 wiLocal;
    float pdf;
    vec3 weight;
    if (lambertian) {
      wiLocal = shared::sampleCosineHemisphere(shared::rngNext2(rng));
      pdf = shared::cosineHemispherePdf(wiLocal.z);
      weight = bsdf.baseColor;
    } else if (!shared::bsdfSampleWeighted(bsdf, woLocal, shared::rngNext3(rng), wiLocal, pdf,
                                           weight)) {
      break;
    }
    dir = shared::worldFromLocal(tf, wiLocal);
    if (!(pdf > 0.0f) || !scatterable(wiLocal, dir)) break;
    throughput *= weight;
    if (bounce >= 2) {  // qlight's roulette: from bounce 2's vertex on, by the throughput
      float survive = std::min(std::max(throughput.r, std::max(throughput.g, throughput.b)),
                               kRouletteMaxSurvival);
      if (shared::rngNextFloat(rng) >= survive) break;
      throughput /= survive;
    }
    origin = above;
    prevPdf = pdf;
  }
  return radiance;
}

PathTraceResult EmbreePathTracer::render(const PathTraceSettings& st) const {
  const uint32_t pixels = st.width * st.height;
  // The basis and pixel mapping of qlight's camera pass (as ray_sets.cpp's cameraRays).
  const render::CameraView& cam = scene_.camera;
  CameraBasis camera;
  camera.forward = glm::normalize(cam.forward);
  vec3 right = glm::normalize(glm::cross(camera.forward, cam.up));
  float tanHalf = std::tan(0.5f * cam.yfov);
  camera.right = right * (tanHalf * float(st.width) / float(st.height));
  camera.up = glm::cross(right, camera.forward) * tanHalf;
  PathTraceResult r;
  r.image.assign(pixels, vec3(0.0f));
  std::vector<double> variance(pixels, 0.0);
  std::atomic<uint32_t> nextRow{0};
  std::atomic<uint64_t> rays{0}, shadowRays{0};
  auto worker = [&] {
    // Embree asks every thread that traces for flush-to-zero and denormals-are-zero.
    _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
    _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
    Counters c;
    for (uint32_t y = nextRow++; y < st.height; y = nextRow++)
      for (uint32_t x = 0; x < st.width; ++x) {
        uint32_t pixel = y * st.width + x;
        vec3 sum(0.0f);
        double lum = 0, lum2 = 0;
        for (uint32_t k = 0; k < st.spp; ++k) {
          vec3 L = samplePixel(pixel, k, st, camera, c);
          if (!std::isfinite(L.x + L.y + L.z)) continue;
          sum += L;
          double l = shared::luminance(L);
          lum += l;
          lum2 += l * l;
        }
        r.image[pixel] = sum / float(st.spp);
        double mean = lum / st.spp;
        if (st.spp > 1) variance[pixel] = std::max(0.0, lum2 / st.spp - mean * mean) / (st.spp - 1);
      }
    rays += c.rays;
    shadowRays += c.shadowRays;
  };
  auto start = std::chrono::steady_clock::now();
  {
    std::vector<std::jthread> pool;
    for (unsigned t = 0; t < std::max(1u, st.threads); ++t) pool.emplace_back(worker);
  }
  r.wallMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  r.rays = rays;
  r.shadowRays = shadowRays;
  r.paths = uint64_t(pixels) * st.spp;
  for (double v : variance) r.meanVarianceSum += v;
  return r;
}

}  // namespace qlight::bench
