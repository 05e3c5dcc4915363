// A plain single-ray path tracer on Embree, the CPU baseline for qlight's
// whole frames: the light transport of qlight's default renderer (NEE with
// lights chosen by power, MIS by the power heuristic, Russian roulette by
// throughput from bounce 2, max depth 8), qlight's own BSDF and sampling code
// (shaders/shared), one rtcIntersect1 per extension ray and one rtcOccluded1
// per shadow ray, pixels shared by plain std::threads; Lambertian materials
// take a Lambertian BSDF's short code. What it leaves out: textures (material
// factors only), normal maps, transmission (the directions below the surface
// end the path), punctual and environment lights (the scene must have emissive
// triangles). It is what "a straightforward Embree path tracer on the same
// cores" does, not a tuned one: no packets, no ray sorting.
#pragma once
#include <embree3/rtcore.h>

#include <cstdint>
#include <vector>

#include "bench/traversal_vs_embree/world_scene.h"
#include "shaders/shared/bsdf.h"

namespace qlight::bench {

struct PathTraceSettings {
  uint32_t width = 256, height = 144;
  uint32_t spp = 8;
  uint32_t maxDepth = 8;  // qlight's: the bounce whose hit only adds emission
  uint32_t seed = 1;
  unsigned threads = 2;
};

struct PathTraceResult {
  std::vector<glm::vec3> image;  // mean radiance per pixel, rows from the top
  // Every ray traced: camera and extension rays (rtcIntersect1) and shadow rays (rtcOccluded1).
  uint64_t rays = 0, shadowRays = 0, paths = 0;
  double wallMs = 0;
  // Sum over pixels of each pixel's estimated variance of its mean (luminance): the image
  // mean's standard error is sqrt(this) / pixels.
  double meanVarianceSum = 0;
};

class EmbreePathTracer {
 public:
  // `rtc` holds the scene's instances as geometry ids (EmbreeTracer's scene).
  // Throws std::runtime_error when the scene has no emissive triangle.
  EmbreePathTracer(const WorldScene& scene, RTCScene rtc);

  PathTraceResult render(const PathTraceSettings& settings) const;

 private:
  struct Light {
    glm::vec3 p0, edge1, edge2;
    glm::vec3 front;  // unit normal of the emitting side
    glm::vec3 emission;
    float area = 0;
    bool doubleSided = false;
  };
  struct Surface;
  struct CameraBasis {
    glm::vec3 forward, right, up;  // right and up span the image plane at distance 1
  };
  struct Counters;

  Surface surfaceAt(const RTCRayHit& rh) const;
  glm::vec3 samplePixel(uint32_t pixel, uint32_t sample, const PathTraceSettings& s,
                        const CameraBasis& camera, Counters& counts) const;
  float selectPdf(uint32_t light) const;
  uint32_t selectLight(float u) const;

  const WorldScene& scene_;
  RTCScene rtc_;
  std::vector<Light> lights_;
  std::vector<float> lightCdf_;                   // inclusive, by power
  std::vector<uint32_t> instanceFirstTriangle_;   // into lightOfTriangle_
  std::vector<uint32_t> lightOfTriangle_;         // kNoLight where the triangle does not emit
  std::vector<float> instanceFrontSign_;          // -1 for mirroring transforms
  std::vector<glm::mat3> instanceNormalMatrix_;   // world from object, for normals
  std::vector<shared::BsdfParams> materialBsdf_;  // per material, from its factors
  std::vector<bool> materialLambertian_;          // render::exactlyLambertian
};

}  // namespace qlight::bench
