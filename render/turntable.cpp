#include "render/turntable.h"

#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "core/error.h"
#include "core/files.h"

extern char** environ;

namespace voltree {

std::optional<std::filesystem::path> FindOnPath(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::string rest = path ? path : "";
  while (!rest.empty()) {
    const size_t colon = rest.find(':');
    const std::string folder = rest.substr(0, colon);
    rest = colon == std::string::npos ? "" : rest.substr(colon + 1);
    const std::filesystem::path candidate = std::filesystem::path(folder.empty() ? "." : folder) / name;
    if (::access(candidate.c_str(), X_OK) == 0 && std::filesystem::is_regular_file(candidate)) return candidate;
  }
  return std::nullopt;
}

void VideoOptions::Check() const {
  if (fps < 1 || fps > 240) Fail("video: fps must be in 1..240, got ", fps);
  for (float c : background)
    if (!(c >= 0 && c <= 1)) Fail("video: background components must be in [0, 1]");
}

VideoWriter::VideoWriter(std::filesystem::path output, int width, int height, const VideoOptions& options)
    : output_(std::move(output)), width_(width), height_(height), options_(options) {
  options.Check();
  if (width < 1 || height < 1) Fail("video: bad frame size ", width, "x", height);
  const std::optional<std::filesystem::path> ffmpeg = FindOnPath("ffmpeg");
  if (!ffmpeg)
    Fail(output_.string(), ": writing a video needs ffmpeg, which is not on PATH (Debian: apt-get install ffmpeg)");
  CheckCanWrite(output_, options.force);
  temporary_ = output_.parent_path() / Str(".", output_.filename().string(), ".partial-", ::getpid());
  // A socket rather than a pipe: send(MSG_NOSIGNAL) reports a dead ffmpeg as an error instead of
  // killing us with SIGPIPE, without touching the process's signal handlers.
  int sockets[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM, 0, sockets) != 0) Fail("video: socketpair failed: ", std::strerror(errno));
  const std::string size = Str(width, "x", height), fps = std::to_string(options.fps);
  std::vector<std::string> args = {"ffmpeg", "-hide_banner", "-loglevel", "error", "-y", "-f", "rawvideo", "-pix_fmt",
                                   "rgb24", "-s", size, "-r", fps, "-i", "-",
                                   // yuv420p needs even sizes
                                   "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-pix_fmt", "yuv420p",
                                   "-r", fps, "-movflags", "+faststart", "-f", "mp4", temporary_.string()};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, sockets[1], 0);
  posix_spawn_file_actions_addclose(&actions, sockets[0]);
  posix_spawn_file_actions_addclose(&actions, sockets[1]);
  pid_t pid = 0;
  const int spawned = ::posix_spawn(&pid, ffmpeg->c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(sockets[1]);
  if (spawned != 0) {
    ::close(sockets[0]);
    Fail("video: could not start ", ffmpeg->string(), ": ", std::strerror(spawned));
  }
  ::shutdown(sockets[0], SHUT_RD);
  socket_ = sockets[0];
  pid_ = pid;
}

VideoWriter::~VideoWriter() {
  if (finished_) return;
  Stop();
  std::error_code ignored;
  std::filesystem::remove(temporary_, ignored);
}

void VideoWriter::Stop() {
  if (socket_ >= 0) ::close(socket_), socket_ = -1;
  if (pid_ > 0) {
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {}
    status_ = status;
    pid_ = -1;
  }
}

void VideoWriter::AddFrame(const Image8& frame) {
  if (frame.width != width_ || frame.height != height_ || (frame.channels != 3 && frame.channels != 4))
    Fail("video: frame is ", frame.width, "x", frame.height, "x", frame.channels, ", expected ", width_, "x", height_,
         " RGB or RGBA");
  if (socket_ < 0) Fail("video: frame added after Finish");
  std::vector<uint8_t> rgb(size_t(width_) * height_ * 3);
  for (size_t p = 0; p < size_t(width_) * height_; ++p) {
    const uint8_t* in = frame.pixels.data() + p * frame.channels;
    const float a = frame.channels == 4 ? in[3] / 255.0f : 1.0f;
    for (int c = 0; c < 3; ++c)
      rgb[3 * p + c] = uint8_t(std::lround(a * in[c] + (1 - a) * 255.0f * options_.background[c]));
  }
  for (size_t sent = 0; sent < rgb.size();) {
    const ssize_t n = ::send(socket_, rgb.data() + sent, rgb.size() - sent, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      Stop();
      Fail(output_.string(), ": ffmpeg stopped reading frames (exit status ",
           WIFEXITED(status_) ? WEXITSTATUS(status_) : -1, "; its messages are above)");
    }
    sent += size_t(n);
  }
}

void VideoWriter::Finish() {
  Stop();
  if (!WIFEXITED(status_) || WEXITSTATUS(status_) != 0)
    Fail(output_.string(), ": ffmpeg failed (exit status ", WIFEXITED(status_) ? WEXITSTATUS(status_) : -1,
         "; its messages are above)");
  if (!options_.force && std::filesystem::exists(output_))
    Fail(output_.string(), " appeared meanwhile; pass --force to replace it");
  std::filesystem::rename(temporary_, output_);
  finished_ = true;
}

}  // namespace voltree
