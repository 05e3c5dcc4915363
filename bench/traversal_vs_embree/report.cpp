#include "bench/traversal_vs_embree/report.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace qlight::bench {
namespace {

std::string format(const char* fmt, auto... args) {
  char buf[256];
  std::snprintf(buf, sizeof buf, fmt, args...);
  return buf;
}

std::string bytes(double b) {
  return b >= 1048576.0 ? format("%.1f MiB", b / 1048576.0) : format("%.1f KiB", b / 1024.0);
}

nlohmann::json setJson(const SetResult& s) {
  const Agreement& a = s.agreement;
  nlohmann::json j = {
      {"kind", s.kind},
      {"any_hit", s.anyHit},
      {"rays", s.rays},
      {"qlight_ms", s.qlightMs},
      {"embree_ms", s.embreeMs},
      {"qlight_median_ms", median(s.qlightMs)},
      {"embree_median_ms", median(s.embreeMs)},
      {"qlight_mrays_per_s", s.qlightMrays()},
      {"embree_mrays_per_s", s.embreeMrays()},
      {"ratio_qlight_to_embree", s.ratio()},
      {"qlight_cpu_ms", s.qlightCpuMs},
      {"embree_cpu_ms", s.embreeCpuMs},
      {"qlight_mrays_per_s_cpu_normalised", s.qlightCpuMrays()},
      {"embree_mrays_per_s_cpu_normalised", s.embreeCpuMrays()},
      {"cpu_ratio_qlight_to_embree", s.cpuRatio()},
      {"agreement",
       {{"mismatches", a.mismatches()},
        {"mismatch_fraction", a.mismatchFraction()},
        {"hit_miss_differ", a.hitMissDiffer},
        {"distance_differ", a.distanceDiffer},
        {"other_triangle_same_distance", a.otherTriangle},
        {"max_relative_distance_difference", a.maxDistanceDifference},
        {"qlight_hits", a.qlightHits},
        {"embree_hits", a.embreeHits},
        {"examples", nlohmann::json::array()}}},
  };
  for (const MismatchExample& m : s.examples) {
    auto hit = [](const shared::TraceHit& h) {
      return nlohmann::json{
          {"hit", h.hit != 0}, {"t", h.t}, {"instance", h.instance}, {"primitive", h.primitive}};
    };
    j["agreement"]["examples"].push_back(
        {{"ray", m.index},
         {"origin", {m.ray.origin.x, m.ray.origin.y, m.ray.origin.z}},
         {"dir", {m.ray.dir.x, m.ray.dir.y, m.ray.dir.z}},
         {"t_max", m.ray.tMax},
         {"qlight", hit(m.qlight)},
         {"embree", hit(m.embree)}});
  }
  if (!s.embreePacketMs.empty()) {
    j["embree_packet8_ms"] = s.embreePacketMs;
    j["embree_packet8_mrays_per_s"] = s.embreePacketMrays();
    j["embree_packet8_mismatches_against_single"] = s.packetMismatches;
  }
  return j;
}

}  // namespace

double median(std::vector<double> v) {
  if (v.empty()) throw std::logic_error("median of nothing");
  std::sort(v.begin(), v.end());
  size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

void printTable(std::ostream& out, const std::vector<SceneResult>& scenes) {
  out << format("%-32s %9s %-10s %8s %8s %7s %7s %10s %9s\n", "scene", "triangles", "rays",
                "qlight", "Embree", "ratio", "ratio", "mismatches", "Embree x8");
  out << format("%-32s %9s %-10s %8s %8s %7s %7s %10s %9s\n", "", "", "", "Mrays/s", "Mrays/s",
                "q/E", "q/E cpu", "", "Mrays/s");
  for (const SceneResult& sc : scenes) {
    for (const SetResult& s : sc.sets) {
      std::string packets = s.embreePacketMs.empty() ? "-" : format("%.2f", s.embreePacketMrays());
      out << format("%-32s %9llu %-10s %8.2f %8.2f %7.3f %7.3f %10llu %9s\n", sc.name.c_str(),
                    (unsigned long long)sc.triangles, s.kind.c_str(), s.qlightMrays(),
                    s.embreeMrays(), s.ratio(), s.cpuRatio(),
                    (unsigned long long)s.agreement.mismatches(), packets.c_str());
    }
  }
  out << "(ratio: wall clock medians; q/E cpu: per CPU second, robust to a busy machine)\n";
  out << "\nBVH builds (ms): qlight BLAS + TLAS | Embree geometry + build (quality high)\n";
  for (const SceneResult& sc : scenes)
    out << format("%-32s %9.1f + %6.1f | %7.1f + %8.1f   memory: qlight %s, Embree %s\n",
                  sc.name.c_str(), sc.qlightBlasMs, sc.qlightTlasMs, sc.embreeGeometryMs,
                  sc.embreeBuildMs, bytes(double(sc.qlightBvhBytes)).c_str(),
                  bytes(double(sc.embreeBytes)).c_str());
}

nlohmann::json toJson(const RunInfo& info, const std::vector<SceneResult>& scenes, bool passed) {
  nlohmann::json j;
  j["benchmark"] = "traversal_vs_embree";
  j["passed"] = passed;
  j["machine"] = {{"cpu", info.cpu},
                  {"vulkan_device", info.vulkanDevice},
                  {"vulkan_validation", info.validation},
                  {"embree_version", info.embreeVersion},
                  {"threads", info.threads},
                  {"load_average_before", info.loadBefore},
                  {"load_average_after", info.loadAfter},
                  {"peak_rss_bytes", info.peakRssBytes}};
  j["settings"] = {{"width", info.width},
                   {"height", info.height},
                   {"repetitions", info.reps},
                   {"quick", info.quick},
                   {"seed", info.seed},
                   {"relative_distance_tolerance", info.relativeTolerance},
                   {"max_mismatch_fraction", info.maxMismatchFraction}};
  j["wall_seconds"] = info.wallSeconds;
  for (const SceneResult& sc : scenes) {
    nlohmann::json s = {
        {"name", sc.name},
        {"path", sc.path},
        {"triangles", sc.triangles},
        {"mesh_triangles", sc.meshTriangles},
        {"instances", sc.instances},
        {"emissive_triangles", sc.emitters},
        {"bounds_diagonal", sc.size},
        {"qlight_bvh",
         {{"blas_build_ms", sc.qlightBlasMs},
          {"tlas_build_ms", sc.qlightTlasMs},
          {"bytes", sc.qlightBvhBytes},
          {"nodes", sc.qlightNodes}}},
        {"embree_bvh",
         {{"geometry_ms", sc.embreeGeometryMs},
          {"build_ms", sc.embreeBuildMs},
          {"bytes", sc.embreeBytes},
          {"peak_bytes", sc.embreePeakBytes}}},
    };
    for (const SetResult& set : sc.sets) s["sets"].push_back(setJson(set));
    j["scenes"].push_back(s);
  }
  return j;
}

}  // namespace qlight::bench
