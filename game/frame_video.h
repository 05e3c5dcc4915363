// The headless demo's frames as a video: DIR/frame_0000.png ... encoded by ffmpeg (H.264,
// yuv420p) when it is on PATH. ffmpeg is optional: without it the frames are the output.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>

namespace qlight::game {

struct VideoResult {
  bool written = false;
  std::string why;  // when not written: one line saying why
};

// Encodes frames 0..frames-1 of `dir`/frame_%04d.png at `fps` into `mp4` (overwritten).
// ffmpeg's own messages go to `dir`/ffmpeg.log, kept only when it fails.
VideoResult encodeFrames(const std::filesystem::path& dir, uint32_t frames, float fps,
                         const std::filesystem::path& mp4);

}  // namespace qlight::game
