// Screenshots of the demo window: the path tracer's converged image (not the
// UI), tonemapped like the display, written as PNG.
#pragma once
#include <filesystem>

#include "engine/render/path_tracer.h"

namespace qlight::game {

// The first of screenshot_0000.png, screenshot_0001.png, ... that does not exist in `dir`.
std::filesystem::path nextScreenshotPath(const std::filesystem::path& dir);

// Waits for the GPU, then writes the mean image (creating parent folders).
void writeScreenshot(const render::PathTracer& tracer, const std::filesystem::path& path,
                     float exposure, image::Tonemap tonemap);

}  // namespace qlight::game
