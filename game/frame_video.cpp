#include "game/frame_video.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

extern char** environ;

namespace qlight::game {

namespace fs = std::filesystem;

VideoResult encodeFrames(const fs::path& dir, uint32_t frames, float fps, const fs::path& mp4) {
  char rate[32];
  std::snprintf(rate, sizeof(rate), "%g", fps);
  // ffmpeg reads a % in the folder's name as part of the pattern: double it.
  std::string pattern;
  for (char c : dir.string()) pattern += c == '%' ? std::string("%%") : std::string(1, c);
  pattern += "/frame_%04d.png";
  const std::string count = std::to_string(frames);
  const fs::path log = dir / "ffmpeg.log";
  std::vector<std::string> args = {
      "ffmpeg", "-nostdin", "-y", "-loglevel", "error", "-framerate", rate, "-start_number", "0",
      "-i", pattern,
      // A folder with frames of an earlier, longer run: take only this run's.
      "-frames:v", count,
      // H.264 in yuv420p needs an even width and height.
      "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-pix_fmt", "yuv420p", "-r", rate,
      mp4.string()};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&files, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&files, 1, 2);
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, "ffmpeg", &files, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&files);
  std::error_code ec;
  if (spawned != 0) {
    fs::remove(log, ec);
    if (spawned == ENOENT) return {false, "ffmpeg is not on PATH (Debian: apt-get install ffmpeg)"};
    return {false, std::string("ffmpeg did not start (") + std::strerror(spawned) + ")"};
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && fs::file_size(mp4, ec) > 0 && !ec) {
    fs::remove(log, ec);
    return {true, ""};
  }
  const std::string how = WIFEXITED(status)
                              ? "exit code " + std::to_string(WEXITSTATUS(status))
                              : "killed by signal " + std::to_string(WTERMSIG(status));
  return {false, "ffmpeg failed (" + how + "); its messages are in " + log.string()};
}

}  // namespace qlight::game
