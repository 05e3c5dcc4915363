// What one run measured, printed as a table and written as JSON.
#pragma once
#include <cstdint>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "bench/traversal_vs_embree/hit_compare.h"

namespace qlight::bench {

double median(std::vector<double> values);

// A ray the two sides disagree on, as both saw it (for the JSON).
struct MismatchExample {
  uint32_t index = 0;
  shared::TraceRay ray{};
  shared::TraceHit qlight{}, embree{};
};

struct SetResult {
  std::string kind;
  bool anyHit = false;
  uint32_t rays = 0;
  std::vector<double> qlightMs, embreeMs, embreePacketMs;  // one per repetition
  // Process CPU time of the same runs (lavapipe's threads or Embree's), so a
  // busy shared machine can be told apart: rays per CPU second x threads is
  // the speed on idle cores, if the threads were kept busy.
  std::vector<double> qlightCpuMs, embreeCpuMs;
  unsigned threads = 1;
  Agreement agreement;
  std::vector<MismatchExample> examples;  // of agreement.examples
  uint64_t packetMismatches = 0;          // Embree's packets against its single rays

  double qlightMrays() const { return rays / median(qlightMs) * 1e-3; }
  double embreeMrays() const { return rays / median(embreeMs) * 1e-3; }
  double embreePacketMrays() const { return rays / median(embreePacketMs) * 1e-3; }
  double ratio() const {
    return qlightMrays() / embreeMrays();
  }  // qlight's share of Embree's speed
  double qlightCpuMrays() const { return rays / median(qlightCpuMs) * threads * 1e-3; }
  double embreeCpuMrays() const { return rays / median(embreeCpuMs) * threads * 1e-3; }
  double cpuRatio() const { return qlightCpuMrays() / embreeCpuMrays(); }
};

struct SceneResult {
  std::string name, path;
  uint64_t triangles = 0;      // over all instances (what Embree holds)
  uint64_t meshTriangles = 0;  // over the meshes (what qlight's BLASes hold)
  uint32_t instances = 0;
  uint32_t emitters = 0;
  float size = 0;  // bounds diagonal
  double qlightBlasMs = 0, qlightTlasMs = 0;
  uint64_t qlightBvhBytes = 0, qlightNodes = 0;
  double embreeGeometryMs = 0, embreeBuildMs = 0;
  int64_t embreeBytes = 0, embreePeakBytes = 0;
  std::vector<SetResult> sets;
};

struct RunInfo {
  std::string cpu, vulkanDevice, embreeVersion;
  unsigned threads = 0;
  uint32_t width = 0, height = 0, reps = 0, seed = 0;
  bool quick = false;
  bool validation = false;  // QLIGHT_VALIDATION=1: slower, checks the Vulkan usage
  float relativeTolerance = 0, maxMismatchFraction = 0;
  double loadBefore[3] = {0, 0, 0}, loadAfter[3] = {0, 0, 0};  // getloadavg: was the machine busy?
  double wallSeconds = 0;
  int64_t peakRssBytes = 0;
};

void printTable(std::ostream& out, const std::vector<SceneResult>& scenes);
nlohmann::json toJson(const RunInfo& info, const std::vector<SceneResult>& scenes, bool passed);

}  // namespace qlight::bench
