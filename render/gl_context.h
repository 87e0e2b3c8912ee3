// A headless OpenGL context: EGL without a window system (Mesa's surfaceless platform, or an
// EGL device such as an NVIDIA GPU), desktop OpenGL core profile, current on the creating thread.
#pragma once

#include <string>

namespace voltree {

struct GlContextOptions {
  int major = 4;  // 4.5 is asked for first, then 4.3
  int minor = 5;
  bool debug = false;
  void Check() const;
};

class GlContext {
 public:
  // Throws Error with an installation hint when no EGL display or no suitable context exists.
  explicit GlContext(const GlContextOptions& options = {});
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  // Makes the context current on the calling thread (it is current after construction).
  void MakeCurrent() const;

  const std::string& renderer() const { return renderer_; }  // e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  const std::string& version() const { return version_; }    // GL_VERSION string
  const std::string& platform() const { return platform_; }  // "surfaceless" or "device"
  int major() const { return major_; }
  int minor() const { return minor_; }
  std::string Describe() const;

 private:
  void* display_ = nullptr;  // EGLDisplay
  void* context_ = nullptr;  // EGLContext
  std::string renderer_, version_, platform_;
  int major_ = 0, minor_ = 0;
};

// Throws Error naming `what` when glGetError reports a problem.
void CheckGl(const char* what);

}  // namespace voltree
