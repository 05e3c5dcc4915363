#include "game/bench/progress_bar.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace qlight::game::bench {

ProgressBar::ProgressBar(double total)
    : total_(std::max(total, 1e-9)), terminal_(isatty(STDERR_FILENO)) {}

ProgressBar::~ProgressBar() { finish(); }

void ProgressBar::update(double done, const std::string& what) {
  double share = std::clamp(done / total_, 0.0, 1.0);
  if (terminal_) {
    constexpr int kWidth = 30;
    int filled = int(share * kWidth);
    std::fprintf(stderr, "\r[%.*s%*s] %3d%% %-40.40s", filled, "##############################",
                 kWidth - filled, "", int(share * 100), what.c_str());
    std::fflush(stderr);
    return;
  }
  int decile = int(share * 10);
  if (decile == lastDecile_) return;
  lastDecile_ = decile;
  std::fprintf(stderr, "qlight bench: %3d%% %s\n", decile * 10, what.c_str());
}

void ProgressBar::finish() {
  if (finished_) return;
  finished_ = true;
  if (terminal_) std::fprintf(stderr, "\n");
}

}  // namespace qlight::game::bench
