#include "game/context_setup.h"

#include <cstdio>

namespace qlight::game {

std::unique_ptr<gpu::Context> createContext(const CommonOptions& common, bool windowed,
                                            std::vector<std::string> instanceExtensions,
                                            std::function<VkSurfaceKHR(VkInstance)> createSurface) {
  gpu::ContextOptions options = gpu::defaultContextOptions();
  options.validation = options.validation || common.validation;
  options.deviceName = common.device;
  if (windowed) {
    options.instanceExtensions = std::move(instanceExtensions);
    options.createSurface = std::move(createSurface);
  }
  return std::make_unique<gpu::Context>(options);
}

int finishContext(const gpu::Context& ctx) {
  size_t n = ctx.validationMessageCount();
  if (n == 0) return 0;
  std::fprintf(stderr, "qlight: the validation layer reported %zu message(s)\n", n);
  return kExitValidation;
}

}  // namespace qlight::game
