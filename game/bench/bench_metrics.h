// The error measures the bench reports (the papers' measures): relative MSE
// against a reference, and the time a method needs to reach an error.
#pragma once
#include <optional>
#include <vector>

#include "engine/image/image_io.h"

namespace qlight::game::bench {

// Mean over pixels and RGB channels of (x - ref)^2 / (ref^2 + 0.01): the usual relMSE
// (the 0.01 keeps black pixels from dominating).
double relativeMse(const image::LinearImage& x, const image::LinearImage& reference);

struct Checkpoint {
  uint32_t spp = 0;
  double seconds = 0;  // cumulative render time of the method
  double relMse = 0;
};

// The time from which a run's error stays at or below `target`, interpolated in log-log
// between checkpoints. When the run never reaches it, extrapolated from the last checkpoint with
// relMSE ~ 1/t (the Monte Carlo rate) and flagged.
struct TimeToError {
  double seconds = 0;
  bool extrapolated = false;
};
std::optional<TimeToError> timeToReach(const std::vector<Checkpoint>& run, double target);

// relMSE at `spp`, interpolated in log-log between checkpoints (none before the first).
std::optional<double> relMseAtSpp(const std::vector<Checkpoint>& run, uint32_t spp);

}  // namespace qlight::game::bench
