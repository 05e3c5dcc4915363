// GPU prefix sums from GPU timestamps: one long scan, and the segmented scan
// the guiding CDFs use (many segments of one point's strata).
#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

#include "engine/gpu/gpu_timer.h"
#include "engine/gpu/prefix_sum.h"

namespace {

using namespace qlight;

gpu::Context& context() {
  static std::unique_ptr<gpu::Context> ctx = [] {
    gpu::ContextOptions o = gpu::defaultContextOptions();
    o.quiet = true;
    return std::make_unique<gpu::Context>(o);
  }();
  return *ctx;
}

// range(0): element count; range(1): segment length (0 = one scan).
void BM_PrefixSum(benchmark::State& state) {
  gpu::Context& ctx = context();
  const uint32_t n = uint32_t(state.range(0)), segment = uint32_t(state.range(1));
  gpu::Buffer data(ctx, uint64_t(n) * 4, "values");
  std::vector<float> ones(n, 1.0f);
  data.upload<float>(ctx, ones);
  gpu::PrefixSum scan(ctx);
  gpu::GpuTimer timer(ctx);
  for (auto _ : state) {
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
      timer.reset(cmd);
      gpu::PassRecorder rec(ctx, cmd, &timer);
      if (segment)
        scan.scanSegments(rec, data, n / segment, segment);
      else
        scan.scan(rec, data, n);
      rec.finish();
    });
    double ms = 0;
    for (auto& [name, t] : timer.collect(ctx)) ms += t;
    state.SetIterationTime(ms * 1e-3);
  }
  state.counters["Gfloats/s"] =
      benchmark::Counter(double(n) * 1e-9, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_PrefixSum)
    ->Args({1 << 20, 0})
    ->Args({1 << 24, 0})
    ->Args({100000 * 64, 64})
    ->Args({16384 * 128, 128})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
