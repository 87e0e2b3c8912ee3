// Turntable videos: frames piped to an ffmpeg child process (H.264, yuv420p, for any player).
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>

#include "core/image.h"

namespace voltree {

// The executable `name` on PATH, if any.
std::optional<std::filesystem::path> FindOnPath(const std::string& name);

struct VideoOptions {
  int fps = 30;
  std::array<float, 3> background = {0.5f, 0.5f, 0.5f};  // straight-alpha frames are composited over it
  bool force = false;                                    // replace an existing file
  void Check() const;
};

// Writes an .mp4 via a temporary sibling that is renamed into place by Finish(); destroyed
// without Finish() (an error) it stops ffmpeg and removes the temporary file. Throws Error when
// ffmpeg is not installed, the output exists without `force`, or ffmpeg fails.
class VideoWriter {
 public:
  VideoWriter(std::filesystem::path output, int width, int height, const VideoOptions& options);
  ~VideoWriter();
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  // RGBA (straight alpha) or RGB frames of the writer's size.
  void AddFrame(const Image8& frame);
  void Finish();

 private:
  void Stop();  // closes the pipe and waits for ffmpeg; returns its exit status via status_
  std::filesystem::path output_, temporary_;
  int width_, height_;
  VideoOptions options_;
  int socket_ = -1;
  int pid_ = -1;
  int status_ = 0;
  bool finished_ = false;
};

}  // namespace voltree
