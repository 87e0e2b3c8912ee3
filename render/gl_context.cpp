#include "render/gl_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <vector>

#include "core/error.h"
#include "render/gl.h"

namespace voltree {
namespace {

constexpr const char* kInstallHint =
    "install libegl-mesa0 and libgl1-mesa-dri (Mesa llvmpipe) or the NVIDIA EGL driver";

std::string EglErrorName(EGLint code) {
  switch (code) {
    case EGL_SUCCESS:
      return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED:
      return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
      return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
      return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
      return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
      return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
      return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY:
      return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
      return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER:
      return "EGL_BAD_PARAMETER";
    default:
      return Str("EGL error 0x", std::hex, code);
  }
}

bool HasExtension(const char* list, const char* name) {
  if (list == nullptr) return false;
  const size_t length = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += length)
    if ((p == list || p[-1] == ' ') && (p[length] == ' ' || p[length] == '\0')) return true;
  return false;
}

// Returns an initialized display or EGL_NO_DISPLAY.
EGLDisplay TryInitialize(EGLDisplay display) {
  if (display == EGL_NO_DISPLAY) return EGL_NO_DISPLAY;
  EGLint major = 0, minor = 0;
  if (eglInitialize(display, &major, &minor) != EGL_TRUE) return EGL_NO_DISPLAY;
  return display;
}

// Mesa's surfaceless platform first (llvmpipe or a Mesa GPU driver), then enumerated EGL devices
// (NVIDIA's driver has no surfaceless platform).
EGLDisplay OpenDisplay(std::string* platform) {
  const char* client_extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (HasExtension(client_extensions, "EGL_MESA_platform_surfaceless")) {
    EGLDisplay display =
        TryInitialize(eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr));
    if (display != EGL_NO_DISPLAY) {
      *platform = "surfaceless";
      return display;
    }
  }
  if (HasExtension(client_extensions, "EGL_EXT_device_enumeration") ||
      HasExtension(client_extensions, "EGL_EXT_device_base")) {
    auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    if (query_devices != nullptr) {
      EGLint count = 0;
      query_devices(0, nullptr, &count);
      std::vector<EGLDeviceEXT> devices(static_cast<size_t>(count));
      if (count > 0 && query_devices(count, devices.data(), &count) == EGL_TRUE) {
        for (EGLDeviceEXT device : devices) {
          EGLDisplay display = TryInitialize(eglGetPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device, nullptr));
          if (display != EGL_NO_DISPLAY) {
            *platform = "device";
            return display;
          }
        }
      }
    }
  }
  return EGL_NO_DISPLAY;
}

EGLConfig ChooseConfig(EGLDisplay display) {
  const EGLint attributes[] = {EGL_RENDERABLE_TYPE,
                               EGL_OPENGL_BIT,
                               EGL_SURFACE_TYPE,
                               EGL_PBUFFER_BIT,
                               EGL_RED_SIZE,
                               8,
                               EGL_GREEN_SIZE,
                               8,
                               EGL_BLUE_SIZE,
                               8,
                               EGL_NONE};
  EGLConfig config = nullptr;
  EGLint count = 0;
  if (eglChooseConfig(display, attributes, &config, 1, &count) == EGL_TRUE && count > 0) return config;
  // Rendering only into framebuffer objects needs no surface, hence no config.
  if (HasExtension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_no_config_context")) return EGL_NO_CONFIG_KHR;
  Fail("EGL: no OpenGL-capable config on this display (", EglErrorName(eglGetError()), "); ", kInstallHint);
}

EGLContext CreateContext(EGLDisplay display, EGLConfig config, int major, int minor, bool debug) {
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                               major,
                               EGL_CONTEXT_MINOR_VERSION,
                               minor,
                               EGL_CONTEXT_OPENGL_PROFILE_MASK,
                               EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                               EGL_CONTEXT_OPENGL_DEBUG,
                               debug ? EGL_TRUE : EGL_FALSE,
                               EGL_NONE};
  return eglCreateContext(display, config, EGL_NO_CONTEXT, attributes);
}

std::string GlString(GLenum name) {
  const auto* text = reinterpret_cast<const char*>(glGetString(name));
  return text != nullptr ? text : "";
}

}  // namespace

void GlContextOptions::Check() const {
  if (major < 3 || (major == 3 && minor < 3) || minor < 0)
    Fail("OpenGL version ", major, ".", minor, " is too old; the renderer needs a core profile of at least 3.3");
}

GlContext::GlContext(const GlContextOptions& options) {
  options.Check();
  EGLDisplay display = OpenDisplay(&platform_);
  if (display == EGL_NO_DISPLAY)
    Fail("no EGL display: neither the surfaceless platform nor an EGL device could be opened (",
         EglErrorName(eglGetError()), "); ", kInstallHint);
  display_ = display;
  if (eglBindAPI(EGL_OPENGL_API) != EGL_TRUE)
    Fail("EGL: desktop OpenGL is not supported by this driver (", EglErrorName(eglGetError()), "); ", kInstallHint);
  const EGLConfig config = ChooseConfig(display);

  // Ask for the requested version, then 4.3 (compute shaders), then the driver's best core profile.
  std::vector<std::pair<int, int>> versions = {{options.major, options.minor}};
  if (options.major > 4 || (options.major == 4 && options.minor > 3)) versions.push_back({4, 3});
  EGLContext context = EGL_NO_CONTEXT;
  for (const auto& [major, minor] : versions) {
    context = CreateContext(display, config, major, minor, options.debug);
    if (context != EGL_NO_CONTEXT) break;
  }
  if (context == EGL_NO_CONTEXT)
    Fail("EGL: cannot create an OpenGL ", versions.back().first, ".", versions.back().second, " core profile context (",
         EglErrorName(eglGetError()), "); ", kInstallHint);
  context_ = context;
  MakeCurrent();
  renderer_ = GlString(GL_RENDERER);
  version_ = GlString(GL_VERSION);
  glGetIntegerv(GL_MAJOR_VERSION, &major_);
  glGetIntegerv(GL_MINOR_VERSION, &minor_);
}

GlContext::~GlContext() {
  // The display is shared by every context of the process (EGL returns the same handle), so it is
  // not terminated here: that would destroy other live contexts.
  if (context_ != nullptr) {
    if (eglGetCurrentContext() == context_) eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
  }
}

void GlContext::MakeCurrent() const {
  if (eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_) != EGL_TRUE)
    Fail("EGL: cannot make the OpenGL context current without a surface (", EglErrorName(eglGetError()),
         "); the driver needs EGL_KHR_surfaceless_context");
}

std::string GlContext::Describe() const {
  return Str("OpenGL ", version_, " on ", renderer_, " (EGL ", platform_, ")");
}

void CheckGl(const char* what) {
  GLenum code = glGetError();
  if (code == GL_NO_ERROR) return;
  std::string codes;
  for (; code != GL_NO_ERROR; code = glGetError()) codes += Str(codes.empty() ? "" : ", ", "0x", std::hex, code);
  Fail("OpenGL error ", codes, " in ", what);
}

}  // namespace voltree
