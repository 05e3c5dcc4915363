// Options every qlight subcommand shares, without CLI11: CLI11's header costs 8 s of
// compile time in each file that includes it, so only the files that add options do.
#pragma once
#include <string>

namespace CLI {
class App;
}

namespace qlight::game {

struct CommonOptions {
  std::string device;  // --device: pick a Vulkan device by name
  bool validation = false;
};

// The guiding options' text, applied after parsing (cli_options.h: finishGuidingOptions).
struct GuidingCli {
  std::string strata;
  std::string nee;  // "", "on" or "off"
};

// Exit code when the validation layer reported something (tests treat it as failure).
constexpr int kExitValidation = 3;

}  // namespace qlight::game
