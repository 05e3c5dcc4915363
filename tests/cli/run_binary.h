// Runs the built qlight binary with arguments; captures exit code and output.
#pragma once
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

namespace qlight::test {

struct RunResult {
  int exitCode = -1;
  std::string output;  // stdout and stderr together
};

inline RunResult runQlight(const std::string& args) {
  std::string cmd = std::string("QLIGHT_VALIDATION=1 ") + QLIGHT_BINARY + " " + args + " 2>&1";
  RunResult r;
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buf;
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0) r.output.append(buf.data(), n);
  int status = pclose(pipe);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

inline std::filesystem::path tempDir(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / ("qlight_test_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::string asset(const char* name) { return std::string(QLIGHT_SOURCE_DIR) + "/assets/" + name; }

}  // namespace qlight::test
