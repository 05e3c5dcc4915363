#include "bench/traversal_vs_embree/embree_tracer.h"

#include <pmmintrin.h>
#include <xmmintrin.h>

#include <chrono>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <thread>

namespace qlight::bench {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

constexpr uint32_t kInvalid = 0xffffffffu;
constexpr TraceHit kMiss{-1.0f, kInvalid, kInvalid, 0u};

// Runs body(begin, end) over [0, count) on `threads` threads, each taking the
// next chunk when it is free (balances uneven rays; chunks keep the shared
// counter and the hit writes of two threads apart); wall-clock ms.
double parallelChunks(size_t count, unsigned threads,
                      const std::function<void(size_t, size_t)>& body) {
  constexpr size_t kChunk = 256;
  std::atomic<size_t> next{0};
  auto worker = [&] {
    // Embree asks every thread that traces for flush-to-zero and
    // denormals-are-zero (its documentation warns of slow denormal arithmetic).
    _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
    _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
    for (size_t b = next.fetch_add(kChunk); b < count; b = next.fetch_add(kChunk))
      body(b, std::min(b + kChunk, count));
  };
  Clock::time_point start = Clock::now();
  {
    std::vector<std::jthread> pool;
    for (unsigned t = 0; t < threads; ++t) pool.emplace_back(worker);
  }
  return msSince(start);
}

void setRay(RTCRay& r, const TraceRay& in) {
  r.org_x = in.origin.x;
  r.org_y = in.origin.y;
  r.org_z = in.origin.z;
  r.tnear = 0.0f;  // qlight counts t > 0; a hit at exactly 0 has measure zero
  r.dir_x = in.dir.x;
  r.dir_y = in.dir.y;
  r.dir_z = in.dir.z;
  r.time = 0.0f;
  r.tfar = in.tMax;
  r.mask = 0xffffffffu;
  r.id = 0;
  r.flags = 0;
}

}  // namespace

std::string embreeVersion() { return RTC_VERSION_STRING; }

// Embree's allocations as they happen (bytes < 0: freed); never refuses one.
bool EmbreeTracer::onMemory(void* user, ssize_t bytes, bool /*post*/) {
  auto* m = static_cast<Memory*>(user);
  int64_t now = m->current.fetch_add(bytes) + bytes;
  int64_t peak = m->peak.load();
  while (now > peak && !m->peak.compare_exchange_weak(peak, now)) {
  }
  return true;
}

EmbreeTracer::EmbreeTracer(const WorldScene& scene, unsigned threads)
    : threads_(threads), memory_(std::make_unique<Memory>()) {
  std::string config = "threads=" + std::to_string(threads);
  device_.reset(rtcNewDevice(config.c_str()));
  if (!device_) throw std::runtime_error("Embree: rtcNewDevice failed");
  rtcSetDeviceMemoryMonitorFunction(device_.get(), onMemory, memory_.get());

  Clock::time_point start = Clock::now();
  scene_.reset(rtcNewScene(device_.get()));
  // Default scene flags: Embree's fast (not RTC_SCENE_FLAG_ROBUST) traversal.
  rtcSetSceneBuildQuality(scene_.get(), RTC_BUILD_QUALITY_HIGH);
  for (uint32_t i = 0; i < scene.instances.size(); ++i) {
    const WorldInstance& inst = scene.instances[i];
    const std::vector<uint32_t>& indices = scene.asset.meshes[inst.mesh].indices;
    RTCGeometry g = rtcNewGeometry(device_.get(), RTC_GEOMETRY_TYPE_TRIANGLE);
    // New buffers (not shared ones): Embree pads them as its SIMD loads need.
    void* v = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                      sizeof(glm::vec3), inst.positions.size());
    void* t = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                      3 * sizeof(uint32_t), indices.size() / 3);
    if (v && !inst.positions.empty())
      std::memcpy(v, inst.positions.data(), inst.positions.size() * sizeof(glm::vec3));
    if (t && !indices.empty()) std::memcpy(t, indices.data(), indices.size() * sizeof(uint32_t));
    rtcSetGeometryBuildQuality(g, RTC_BUILD_QUALITY_HIGH);
    rtcCommitGeometry(g);
    rtcAttachGeometryByID(scene_.get(), g, i);
    rtcReleaseGeometry(g);  // the scene keeps it
  }
  check("geometry");
  geometryMs_ = msSince(start);
  start = Clock::now();
  rtcCommitScene(scene_.get());
  buildMs_ = msSince(start);
  check("rtcCommitScene");
}

void EmbreeTracer::check(const char* what) const {
  RTCError e = rtcGetDeviceError(device_.get());
  if (e != RTC_ERROR_NONE)
    throw std::runtime_error(std::string("Embree: ") + what + " failed (error " +
                             std::to_string(int(e)) + ")");
}

double EmbreeTracer::trace(const RaySet& set, std::vector<TraceHit>& hits) const {
  hits.assign(set.rays.size(), kMiss);
  RTCScene scene = scene_.get();
  const TraceRay* rays = set.rays.data();
  TraceHit* out = hits.data();
  if (set.anyHit) {
    return parallelChunks(set.rays.size(), threads_, [=](size_t b, size_t e) {
      RTCIntersectContext ctx;
      rtcInitIntersectContext(&ctx);
      for (size_t i = b; i < e; ++i) {
        RTCRay r;
        setRay(r, rays[i]);
        rtcOccluded1(scene, &ctx, &r);
        if (r.tfar < 0.0f) out[i] = {-1.0f, kInvalid, kInvalid, 1u};  // tfar = -inf: occluded
      }
    });
  }
  return parallelChunks(set.rays.size(), threads_, [=](size_t b, size_t e) {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    for (size_t i = b; i < e; ++i) {
      RTCRayHit rh;
      setRay(rh.ray, rays[i]);
      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(scene, &ctx, &rh);
      if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID)
        out[i] = {rh.ray.tfar, rh.hit.geomID, rh.hit.primID, 1u};
    }
  });
}

double EmbreeTracer::tracePackets8(const RaySet& set, std::vector<TraceHit>& hits) const {
  hits.assign(set.rays.size(), kMiss);
  RTCScene scene = scene_.get();
  const TraceRay* rays = set.rays.data();
  TraceHit* out = hits.data();
  const bool anyHit = set.anyHit;
  // Chunks are multiples of 8, so a packet never straddles two chunks.
  return parallelChunks(set.rays.size(), threads_, [=](size_t b, size_t e) {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    for (size_t p = b; p < e; p += 8) {
      alignas(32) int valid[8];
      RTCRayHit8 rh;
      for (int k = 0; k < 8; ++k) {
        size_t i = p + k;
        valid[k] = i < e ? -1 : 0;
        const TraceRay& r = rays[i < e ? i : p];
        rh.ray.org_x[k] = r.origin.x;
        rh.ray.org_y[k] = r.origin.y;
        rh.ray.org_z[k] = r.origin.z;
        rh.ray.tnear[k] = 0.0f;
        rh.ray.dir_x[k] = r.dir.x;
        rh.ray.dir_y[k] = r.dir.y;
        rh.ray.dir_z[k] = r.dir.z;
        rh.ray.time[k] = 0.0f;
        rh.ray.tfar[k] = r.tMax;
        rh.ray.mask[k] = 0xffffffffu;
        rh.ray.id[k] = 0;
        rh.ray.flags[k] = 0;
        rh.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
      }
      if (anyHit) {
        rtcOccluded8(valid, scene, &ctx, &rh.ray);
        for (int k = 0; k < 8 && p + k < e; ++k)
          if (rh.ray.tfar[k] < 0.0f) out[p + k] = {-1.0f, kInvalid, kInvalid, 1u};
      } else {
        rtcIntersect8(valid, scene, &ctx, &rh);
        for (int k = 0; k < 8 && p + k < e; ++k)
          if (rh.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID)
            out[p + k] = {rh.ray.tfar[k], rh.hit.geomID[k], rh.hit.primID[k], 1u};
      }
    }
  });
}

}  // namespace qlight::bench
