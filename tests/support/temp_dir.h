// A folder of the test process's own under the system's temporary folder, removed when the
// process exits (ctest runs each test case in a process of its own), so runs leave nothing.
#pragma once
#include <unistd.h>

#include <filesystem>
#include <map>
#include <string>
#include <system_error>

namespace qlight::test {

inline std::filesystem::path processTempDir(const std::string& name) {
  struct RemovedAtExit {
    std::map<std::string, std::filesystem::path> dirs;
    ~RemovedAtExit() {
      std::error_code ignored;
      for (const auto& [key, dir] : dirs) std::filesystem::remove_all(dir, ignored);
    }
  };
  static RemovedAtExit made;
  auto [it, added] = made.dirs.try_emplace(name);
  if (added)
    it->second = std::filesystem::temp_directory_path() /
                 ("qlight_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::create_directories(it->second);
  return it->second;
}

}  // namespace qlight::test
