// qlight: a path tracer that learns where light comes from.
//   qlight render ...   one image, headless
//   qlight demo ...     the flythrough (a window, or headless frames without a display)
//   qlight bench ...    guided vs unguided at equal time, with plots and a report
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>

#include "game/bench/bench_command.h"
#include "game/cli_options.h"
#include "game/demo_command.h"
#include "game/render_command.h"

int main(int argc, char** argv) {
  using namespace qlight::game;
  CLI::App app{"qlight: Q-learned importance sampling in a realtime Vulkan path tracer"};
  app.require_subcommand(1);
  CommonOptions common;
  app.add_option("--device", common.device,
                 "Vulkan device whose name contains this text (else $QLIGHT_DEVICE, else a "
                 "discrete GPU first)");
  app.add_flag("--validation", common.validation,
               "enable the Khronos validation layer (also QLIGHT_VALIDATION=1)");
  auto render = addRenderCommand(app, common);
  auto demo = addDemoCommand(app, common);
  auto bench = addBenchCommand(app, common);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    for (auto& run : {render, demo, bench}) {
      int rc = run();
      if (rc >= 0) return rc;
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "qlight: error: %s\n", e.what());
    return 1;
  }
}
