#include "game/demo_window.h"

#include <cstdio>

namespace qlight::game {

int runWindowed(const DemoArgs&, const CommonOptions&) {
  std::fprintf(stderr, "qlight demo: the windowed mode is not built yet; use --headless\n");
  return 2;
}

}  // namespace qlight::game
