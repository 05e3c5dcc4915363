#include "engine/gpu/prefix_sum.h"

#include <cmath>
#include <random>

#include "tests/gpu/gpu_fixture.h"

namespace qlight::test {
namespace {

// Each GPU output sums along a path of at most ~30 float additions (4 in a
// thread, 8 Hillis-Steele steps, the same again for the tile level, one add
// back), so its error is bounded by 32 * 2^-24 times the exact prefix.
constexpr double kRelativeBound = 32.0 * 5.9604644775390625e-8;

std::vector<float> randomValues(size_t n, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<float> v(n);
  for (float& x : v) x = u(rng);
  return v;
}

void expectScanned(const std::vector<float>& input, const std::vector<float>& gpu,
                   size_t segmentLength) {
  double exact = 0.0;
  size_t bad = 0;
  for (size_t i = 0; i < input.size(); ++i) {
    if (segmentLength && i % segmentLength == 0) exact = 0.0;
    exact += input[i];
    if (std::abs(gpu[i] - exact) > kRelativeBound * exact + 1e-30 && bad++ < 5)
      ADD_FAILURE() << "element " << i << ": gpu " << gpu[i] << " exact " << exact;
  }
  EXPECT_EQ(bad, 0u);
}

class PrefixSumTest : public GpuTest {};

TEST_F(PrefixSumTest, OneMillionFloatsMatchCpu) {
  const uint32_t n = 1u << 20;
  auto input = randomValues(n, 7);
  gpu::Buffer data(ctx(), n * sizeof(float), "values");
  data.upload<float>(ctx(), input);
  gpu::PrefixSum scan(ctx());
  ctx().submitAndWait([&](VkCommandBuffer cmd) {
    gpu::PassRecorder rec(ctx(), cmd);
    scan.scan(rec, data, n);
    rec.finish();
  });
  expectScanned(input, data.read<float>(ctx()), 0);
}

TEST_F(PrefixSumTest, LengthsAroundTileBoundaries) {
  gpu::PrefixSum scan(ctx());
  for (uint32_t n : {1u, 255u, 1023u, 1024u, 1025u, 4097u, 1024u * 1024u + 3u}) {
    auto input = randomValues(n, n);
    gpu::Buffer data(ctx(), n * sizeof(float), "values");
    data.upload<float>(ctx(), input);
    ctx().submitAndWait([&](VkCommandBuffer cmd) {
      gpu::PassRecorder rec(ctx(), cmd);
      scan.scan(rec, data, n);
      rec.finish();
    });
    SCOPED_TRACE(n);
    expectScanned(input, data.read<float>(ctx()), 0);
  }
}

TEST_F(PrefixSumTest, HundredThousandSegmentsOf64MatchCpu) {
  const uint32_t segments = 100000, length = 64;
  auto input = randomValues(size_t(segments) * length, 11);
  gpu::Buffer data(ctx(), input.size() * sizeof(float), "cdf");
  data.upload<float>(ctx(), input);
  gpu::PrefixSum scan(ctx());
  ctx().submitAndWait([&](VkCommandBuffer cmd) {
    gpu::PassRecorder rec(ctx(), cmd);
    scan.scanSegments(rec, data, segments, length);
    rec.finish();
  });
  expectScanned(input, data.read<float>(ctx()), length);
}

TEST_F(PrefixSumTest, SegmentLengthsThatDoNotDivideTheTile) {
  gpu::PrefixSum scan(ctx());
  for (uint32_t length : {1u, 3u, 100u, 128u, 1000u, 1024u}) {
    const uint32_t segments = 37;
    auto input = randomValues(size_t(segments) * length, length);
    gpu::Buffer data(ctx(), input.size() * sizeof(float), "cdf");
    data.upload<float>(ctx(), input);
    ctx().submitAndWait([&](VkCommandBuffer cmd) {
      gpu::PassRecorder rec(ctx(), cmd);
      scan.scanSegments(rec, data, segments, length);
      rec.finish();
    });
    SCOPED_TRACE(length);
    expectScanned(input, data.read<float>(ctx()), length);
  }
}

TEST_F(PrefixSumTest, RejectsSegmentsLongerThanATile) {
  gpu::PrefixSum scan(ctx());
  gpu::Buffer data(ctx(), 4096 * sizeof(float), "cdf");
  ctx().submitAndWait([&](VkCommandBuffer cmd) {
    gpu::PassRecorder rec(ctx(), cmd);
    EXPECT_THROW(scan.scanSegments(rec, data, 2, 2048), std::invalid_argument);
    EXPECT_THROW(scan.scan(rec, data, 5000), std::invalid_argument);
  });
}

}  // namespace
}  // namespace qlight::test
