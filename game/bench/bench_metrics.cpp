#include "game/bench/bench_metrics.h"

#include <cmath>
#include <stdexcept>

namespace qlight::game::bench {
namespace {

// y at x on the log-log line through (x0, y0) and (x1, y1).
double logLogInterpolate(double x0, double y0, double x1, double y1, double x) {
  if (x1 <= x0 || y0 <= 0 || y1 <= 0) return y1;
  double t = (std::log(x) - std::log(x0)) / (std::log(x1) - std::log(x0));
  return std::exp(std::log(y0) + t * (std::log(y1) - std::log(y0)));
}

}  // namespace

double relativeMse(const image::LinearImage& x, const image::LinearImage& reference) {
  if (x.width != reference.width || x.height != reference.height ||
      x.rgba.size() != reference.rgba.size())
    throw std::invalid_argument("relative MSE of images of different sizes");
  double sum = 0;
  size_t n = 0;
  for (size_t i = 0; i < x.rgba.size(); i += 4)
    for (int c = 0; c < 3; ++c) {
      double r = reference.rgba[i + c], d = double(x.rgba[i + c]) - r;
      sum += d * d / (r * r + 0.01);
      ++n;
    }
  return n ? sum / double(n) : 0.0;
}

std::optional<TimeToError> timeToReach(const std::vector<Checkpoint>& run, double target) {
  if (run.empty() || !(target > 0)) return std::nullopt;
  // The first checkpoint from which the error stays at or below the target: a firefly can
  // lift a run's error above a level it had reached, so the first crossing alone would
  // credit a method with a level it did not hold.
  size_t i = run.size();
  while (i > 0 && run[i - 1].relMse <= target) --i;
  if (i == run.size()) {
    const Checkpoint& last = run.back();
    return TimeToError{last.seconds * last.relMse / target, true};
  }
  if (i == 0) return TimeToError{run[0].seconds, false};
  const Checkpoint &a = run[i - 1], &b = run[i];
  // relMSE falls between a and b: the time on the log-log line where it equals the target.
  if (a.relMse <= 0 || b.relMse <= 0 || a.seconds <= 0) return TimeToError{b.seconds, false};
  double t = (std::log(target) - std::log(a.relMse)) / (std::log(b.relMse) - std::log(a.relMse));
  return TimeToError{
      std::exp(std::log(a.seconds) + t * (std::log(b.seconds) - std::log(a.seconds))), false};
}

std::optional<double> relMseAtSpp(const std::vector<Checkpoint>& run, uint32_t spp) {
  for (size_t i = 0; i < run.size(); ++i) {
    if (run[i].spp < spp) continue;
    if (run[i].spp == spp || i == 0)
      return i == 0 && run[i].spp != spp ? std::nullopt : std::optional(run[i].relMse);
    return logLogInterpolate(run[i - 1].spp, run[i - 1].relMse, run[i].spp, run[i].relMse, spp);
  }
  return std::nullopt;
}

}  // namespace qlight::game::bench
