#include "game/window_screenshot.h"

#include <cstdio>
#include <stdexcept>

namespace qlight::game {

std::filesystem::path nextScreenshotPath(const std::filesystem::path& dir) {
  for (int i = 0; i < 10000; ++i) {
    char name[32];
    std::snprintf(name, sizeof(name), "screenshot_%04d.png", i);
    if (!std::filesystem::exists(dir / name)) return dir / name;
  }
  throw std::runtime_error(dir.string() + ": 10000 screenshots already; clear the folder");
}

void writeScreenshot(const render::PathTracer& tracer, const std::filesystem::path& path,
                     float exposure, image::Tonemap tonemap) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  image::writeImage(path, tracer.readImage(), exposure, tonemap);
  std::printf("qlight demo: screenshot %s\n", path.string().c_str());
}

}  // namespace qlight::game
