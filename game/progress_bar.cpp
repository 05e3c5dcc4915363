#include "game/progress_bar.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <utility>

namespace qlight::game {

ProgressBar::ProgressBar(double total, std::string label, double quietSeconds)
    : total_(std::max(total, 1e-9)),
      label_(std::move(label)),
      quietSeconds_(quietSeconds),
      terminal_(isatty(STDERR_FILENO)) {}

ProgressBar::~ProgressBar() { finish(); }

void ProgressBar::update(double done, const std::string& what) {
  if (finished_) return;
  const double share = std::clamp(done / total_, 0.0, 1.0);
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (elapsed < quietSeconds_) return;
  shown_ = true;
  if (terminal_) {
    constexpr int kWidth = 30;
    const int filled = int(share * kWidth);
    char left[32] = "";
    if (share > 0.0 && share < 1.0)
      std::snprintf(left, sizeof(left), "%.0f s left", elapsed * (1.0 - share) / share);
    std::fprintf(stderr, "\r[%.*s%*s] %3d%% %-40.40s %-12s", filled,
                 "##############################", kWidth - filled, "", int(share * 100),
                 what.c_str(), left);
    std::fflush(stderr);
    return;
  }
  const int decile = int(share * 10);
  if (decile == lastDecile_) return;
  lastDecile_ = decile;
  std::fprintf(stderr, "%s: %3d%% %s\n", label_.c_str(), decile * 10, what.c_str());
}

void ProgressBar::finish() {
  if (finished_) return;
  finished_ = true;
  if (terminal_ && shown_) std::fprintf(stderr, "\n");
}

}  // namespace qlight::game
