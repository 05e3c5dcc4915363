// A virtual X server for window tests: uses $DISPLAY when set, else starts
// `Xvfb :N` as a child process and stops it again (by its pid) at the end.
#pragma once
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>

extern char** environ;

namespace qlight::test {

class XvfbServer {
 public:
  static bool installed() { return std::system("command -v Xvfb >/dev/null 2>&1") == 0; }

  // Returns the display to use, or "" when none could be had (`error` says why).
  std::string start(int number, std::string& error) {
    const char* existing = std::getenv("DISPLAY");
    if (existing && *existing) return existing;
    std::string display = ":" + std::to_string(number);
    std::filesystem::path socket = "/tmp/.X11-unix/X" + std::to_string(number);
    if (std::filesystem::exists(socket)) return display;  // a server already runs there
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    std::string screen = "1024x768x24";
    char* argv[] = {const_cast<char*>("Xvfb"), display.data(), const_cast<char*>("-screen"),
                    const_cast<char*>("0"),    screen.data(),  const_cast<char*>("-nolisten"),
                    const_cast<char*>("tcp"),  nullptr};
    int rc = posix_spawnp(&pid_, "Xvfb", &actions, nullptr, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    if (rc != 0) {
      pid_ = -1;
      error = "posix_spawnp(Xvfb) failed";
      return "";
    }
    for (int i = 0; i < 100; ++i) {  // up to 10 s for the socket
      if (std::filesystem::exists(socket)) return display;
      int status = 0;
      if (waitpid(pid_, &status, WNOHANG) == pid_) {
        pid_ = -1;
        error = "Xvfb " + display + " exited at start";
        return "";
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    error = "Xvfb " + display + " did not open its socket within 10 s";
    return "";
  }

  ~XvfbServer() {
    if (pid_ <= 0) return;
    kill(pid_, SIGTERM);
    int status = 0;
    waitpid(pid_, &status, 0);
  }

 private:
  pid_t pid_ = -1;
};

}  // namespace qlight::test
