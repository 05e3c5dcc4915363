// Creates the Vulkan context from the command line options and reports
// validation messages at exit (non-zero exit when there were any).
#pragma once
#include <functional>
#include <memory>

#include "engine/gpu/context.h"
#include "game/common_options.h"

namespace qlight::game {

std::unique_ptr<gpu::Context> createContext(
    const CommonOptions& common, bool windowed, std::vector<std::string> instanceExtensions = {},
    std::function<VkSurfaceKHR(VkInstance)> createSurface = {});

// 0, or kExitValidation after printing how many validation messages there were.
int finishContext(const gpu::Context& ctx);

}  // namespace qlight::game
