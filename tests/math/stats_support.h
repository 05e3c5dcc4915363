// Statistics for the sampling tests: a test-side random source independent of
// the RNG under test, and Pearson's chi-square with a p = 1e-4 threshold.
#pragma once

#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace qlight::test {

// Uniform floats in [0, 1) from mt19937 (top 24 bits, so never 1.0).
class TestRandom {
 public:
  explicit TestRandom(uint32_t seed) : gen_(seed) {}
  float next() { return float(gen_() >> 8) * (1.0f / 16777216.0f); }
  double nextDouble() { return std::generate_canonical<double, 64>(gen_); }
  glm::vec2 next2() {
    float x = next();
    return glm::vec2(x, next());
  }
  glm::vec3 next3() {
    float x = next();
    float y = next();
    return glm::vec3(x, y, next());
  }

 private:
  std::mt19937 gen_;
};

// Upper 1e-4 quantile of the standard normal.
inline constexpr double kNormalQuantileP1e4 = 3.7190164854556804;
// Two-sided 1e-4 quantile (|z| exceeds it with probability 1e-4).
inline constexpr double kNormalQuantileTwoSidedP1e4 = 3.8905918864131;

// Wilson-Hilferty: chi2_k quantile ~ k (1 - 2/(9k) + z sqrt(2/(9k)))^3.
inline double chiSquareCritical(double dof, double z = kNormalQuantileP1e4) {
  double a = 2.0 / (9.0 * dof);
  double c = 1.0 - a + z * std::sqrt(a);
  return dof * c * c * c;
}

struct ChiSquareResult {
  double statistic = 0.0;
  int dof = 0;
  double critical = 0.0;
  bool pass() const { return dof > 0 && statistic < critical; }
  std::string describe() const {
    return "chi2 = " + std::to_string(statistic) + ", dof = " + std::to_string(dof) +
           ", critical(p=1e-4) = " + std::to_string(critical);
  }
};

// Pearson's test; bins expecting fewer than 5 counts are pooled into one bin
// (merged into the smallest kept bin if the pool itself stays below 5). A
// count where nothing is expected fails outright.
inline ChiSquareResult chiSquareTest(const std::vector<double>& observed,
                                     const std::vector<double>& expected) {
  constexpr double kMinExpected = 5.0;
  ChiSquareResult result;
  double pooledObserved = 0.0;
  double pooledExpected = 0.0;
  std::vector<double> keptObserved;
  std::vector<double> keptExpected;
  for (size_t i = 0; i < observed.size(); ++i) {
    if (expected[i] <= 0.0 && observed[i] > 0.0) {
      result.statistic = std::numeric_limits<double>::infinity();
      result.dof = 1;
      result.critical = chiSquareCritical(1.0);
      return result;
    }
    if (expected[i] < kMinExpected) {
      pooledObserved += observed[i];
      pooledExpected += expected[i];
    } else {
      keptObserved.push_back(observed[i]);
      keptExpected.push_back(expected[i]);
    }
  }
  if (pooledExpected >= kMinExpected) {
    keptObserved.push_back(pooledObserved);
    keptExpected.push_back(pooledExpected);
  } else if (pooledExpected > 0.0 || pooledObserved > 0.0) {
    size_t smallest = 0;
    for (size_t i = 1; i < keptExpected.size(); ++i)
      if (keptExpected[i] < keptExpected[smallest]) smallest = i;
    if (keptExpected.empty()) {
      keptObserved.push_back(0.0);
      keptExpected.push_back(0.0);
    }
    keptObserved[smallest] += pooledObserved;
    keptExpected[smallest] += pooledExpected;
  }
  for (size_t i = 0; i < keptObserved.size(); ++i) {
    double d = keptObserved[i] - keptExpected[i];
    result.statistic += d * d / keptExpected[i];
  }
  result.dof = int(keptObserved.size()) - 1;
  result.critical = result.dof > 0 ? chiSquareCritical(result.dof) : 0.0;
  return result;
}

}  // namespace qlight::test
