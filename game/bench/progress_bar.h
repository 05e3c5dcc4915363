// A one-line progress bar on the terminal (stderr), redrawn in place; on a pipe
// or file it prints a line per 10% instead, so logs stay short.
#pragma once
#include <string>

namespace qlight::game::bench {

class ProgressBar {
 public:
  explicit ProgressBar(double total);
  ~ProgressBar();
  // `done` of the total, with what is running now.
  void update(double done, const std::string& what);
  void finish();

 private:
  double total_;
  bool terminal_;
  int lastDecile_ = -1;
  bool finished_ = false;
};

}  // namespace qlight::game::bench
