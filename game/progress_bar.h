// A one-line progress bar on the terminal (stderr), redrawn in place with the time left; on a
// pipe or file it prints a line per 10% instead, so logs stay short. It stays silent for its
// first seconds: runs that end sooner print nothing.
#pragma once
#include <chrono>
#include <string>

namespace qlight::game {

class ProgressBar {
 public:
  static constexpr double kQuietSeconds = 2.0;

  // `label` starts the lines on a pipe ("qlight bench").
  ProgressBar(double total, std::string label, double quietSeconds = kQuietSeconds);
  ~ProgressBar();
  // `done` of the total, with what is running now.
  void update(double done, const std::string& what);
  void finish();

 private:
  double total_;
  std::string label_;
  double quietSeconds_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  bool terminal_;
  bool shown_ = false;  // something was drawn (the terminal's line then needs ending)
  int lastDecile_ = -1;
  bool finished_ = false;
};

}  // namespace qlight::game
