// Runs the built qlight binary with arguments; captures exit code and output.
#pragma once
#include <unistd.h>

#include <filesystem>
#include <string>

#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

namespace qlight::test {

inline RunResult runQlight(const std::string& args) {
  return runCommand(std::string("QLIGHT_VALIDATION=1 ") + QLIGHT_BINARY + " " + args);
}

inline std::filesystem::path tempDir(const std::string& name) {
  return processTempDir("test_" + name);
}

inline std::string asset(const char* name) {
  return std::string(QLIGHT_SOURCE_DIR) + "/assets/" + name;
}

}  // namespace qlight::test
