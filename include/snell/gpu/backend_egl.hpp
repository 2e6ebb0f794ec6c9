// EGL backend: a GL 4.5 core context without any window or surface.
// On CPU-only machines EGL_PLATFORM_SURFACELESS_MESA gives llvmpipe; on
// machines with a GPU driver EGL_EXT_platform_device picks the first device
// (forced with SNELL_EGL_DEVICE=1). This is the path that survives Mesa 25.1,
// which removed OSMesa.
#pragma once

#include "backend.hpp"
#include "dynamic_library.hpp"

// Types and enums only: every EGL call goes through pointers from the
// dlopen()ed libEGL, so the binary never links it.
#ifndef EGL_EGL_PROTOTYPES
#  define EGL_EGL_PROTOTYPES 0
#endif
#ifndef EGL_NO_X11
#  define EGL_NO_X11
#endif
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <string>

namespace snell::gpu::detail {

inline const char* eglErrorName(EGLint code) {
  switch (code) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_CURRENT_SURFACE: return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_NATIVE_PIXMAP: return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW: return "EGL_BAD_NATIVE_WINDOW";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    case EGL_CONTEXT_LOST: return "EGL_CONTEXT_LOST";
    default: return "unknown EGL error";
  }
}

inline bool hasExtension(const char* list, const char* name) {
  if (list == nullptr) return false;
  const std::size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

struct EglFunctions {
  PFNEGLGETPROCADDRESSPROC GetProcAddress = nullptr;
  PFNEGLGETERRORPROC GetError = nullptr;
  PFNEGLQUERYSTRINGPROC QueryString = nullptr;
  PFNEGLINITIALIZEPROC Initialize = nullptr;
  PFNEGLTERMINATEPROC Terminate = nullptr;
  PFNEGLBINDAPIPROC BindAPI = nullptr;
  PFNEGLCREATECONTEXTPROC CreateContext = nullptr;
  PFNEGLDESTROYCONTEXTPROC DestroyContext = nullptr;
  PFNEGLMAKECURRENTPROC MakeCurrent = nullptr;
  PFNEGLGETPLATFORMDISPLAYEXTPROC GetPlatformDisplayEXT = nullptr;  // EGL_EXT_platform_base
  PFNEGLQUERYDEVICESEXTPROC QueryDevicesEXT = nullptr;              // EGL_EXT_device_enumeration
};

// Platform displays are per process: every eglGetPlatformDisplayEXT with the
// same arguments returns the same EGLDisplay, and eglTerminate would tear down
// the contexts of every snell::gpu::Context on it. Count the users instead.
inline std::map<EGLDisplay, int>& eglDisplayUsers() {
  static std::map<EGLDisplay, int> users;
  return users;
}
inline std::mutex& eglDisplayMutex() {
  static std::mutex m;
  return m;
}

class EglContext final : public BackendContext {
 public:
  EglContext() {
    std::string why;
    lib_ = openLibrary({"libEGL.so.1", "libEGL.so"}, why);
    if (lib_.handle == nullptr)
      throw Error("EGL backend: cannot load libEGL.so.1 or libEGL.so (" + why +
                  "); install libegl1 and libegl-mesa0 (Debian/Ubuntu) or set SNELL_GL_BACKEND=osmesa");
    const char* b = "EGL";
    egl_.GetProcAddress = requireSymbol<PFNEGLGETPROCADDRESSPROC>(lib_, "eglGetProcAddress", b);
    egl_.GetError = requireSymbol<PFNEGLGETERRORPROC>(lib_, "eglGetError", b);
    egl_.QueryString = requireSymbol<PFNEGLQUERYSTRINGPROC>(lib_, "eglQueryString", b);
    egl_.Initialize = requireSymbol<PFNEGLINITIALIZEPROC>(lib_, "eglInitialize", b);
    egl_.Terminate = requireSymbol<PFNEGLTERMINATEPROC>(lib_, "eglTerminate", b);
    egl_.BindAPI = requireSymbol<PFNEGLBINDAPIPROC>(lib_, "eglBindAPI", b);
    egl_.CreateContext = requireSymbol<PFNEGLCREATECONTEXTPROC>(lib_, "eglCreateContext", b);
    egl_.DestroyContext = requireSymbol<PFNEGLDESTROYCONTEXTPROC>(lib_, "eglDestroyContext", b);
    egl_.MakeCurrent = requireSymbol<PFNEGLMAKECURRENTPROC>(lib_, "eglMakeCurrent", b);
    egl_.GetPlatformDisplayEXT =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(egl_.GetProcAddress("eglGetPlatformDisplayEXT"));
    egl_.QueryDevicesEXT = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(egl_.GetProcAddress("eglQueryDevicesEXT"));

    openDisplay();
    try {
      createContext();
    } catch (...) {
      releaseDisplay();
      throw;
    }
  }

  ~EglContext() override {
    if (currentOnThisThread() == this) {
      unbind();
      currentOnThisThread() = nullptr;
    }
    egl_.DestroyContext(display_, context_);
    releaseDisplay();
  }

  void bind() override {
    if (!egl_.MakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
      throw Error(std::string("EGL backend: eglMakeCurrent failed: ") + eglErrorName(egl_.GetError()));
  }
  void unbind() override {
    egl_.MakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }
  void* getProc(const char* name) const override { return reinterpret_cast<void*>(egl_.GetProcAddress(name)); }

  const std::string& platform() const { return platform_; }

 private:
  DynamicLibrary lib_;
  EglFunctions egl_;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  std::string platform_;  // "surfaceless" or "device"

  std::string lastError() const { return eglErrorName(egl_.GetError()); }

  // Returns an initialized display or EGL_NO_DISPLAY with `why` explaining.
  EGLDisplay trySurfaceless(const char* clientExts, std::string& why) {
    if (!hasExtension(clientExts, "EGL_MESA_platform_surfaceless")) {
      why = "surfaceless: EGL_MESA_platform_surfaceless not offered (needs libegl-mesa0)";
      return EGL_NO_DISPLAY;
    }
    EGLDisplay d = egl_.GetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (d == EGL_NO_DISPLAY) why = "surfaceless: eglGetPlatformDisplayEXT failed: " + lastError();
    return d;
  }
  EGLDisplay tryDevice(const char* clientExts, std::string& why) {
    if (!hasExtension(clientExts, "EGL_EXT_platform_device") || egl_.QueryDevicesEXT == nullptr) {
      why = "device: EGL_EXT_platform_device / eglQueryDevicesEXT not offered";
      return EGL_NO_DISPLAY;
    }
    EGLDeviceEXT devices[16];
    EGLint count = 0;
    if (!egl_.QueryDevicesEXT(16, devices, &count) || count < 1) {
      why = "device: eglQueryDevicesEXT found no device (" + lastError() + ")";
      return EGL_NO_DISPLAY;
    }
    EGLDisplay d = egl_.GetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[0], nullptr);
    if (d == EGL_NO_DISPLAY) why = "device: eglGetPlatformDisplayEXT failed: " + lastError();
    return d;
  }

  void openDisplay() {
    if (egl_.GetPlatformDisplayEXT == nullptr)
      throw Error("EGL backend: eglGetPlatformDisplayEXT is missing (EGL_EXT_platform_base); install libegl-mesa0");
    const char* clientExts = egl_.QueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    const char* env = std::getenv("SNELL_EGL_DEVICE");
    const bool deviceFirst = env != nullptr && std::strcmp(env, "1") == 0;
    std::string reasons;
    for (int attempt = 0; attempt < 2; ++attempt) {
      const bool device = (attempt == 0) == deviceFirst;
      std::string why;
      EGLDisplay d = device ? tryDevice(clientExts, why) : trySurfaceless(clientExts, why);
      if (d != EGL_NO_DISPLAY) {
        std::lock_guard<std::mutex> lock(eglDisplayMutex());
        EGLint major = 0, minor = 0;
        if (eglDisplayUsers()[d] > 0 || egl_.Initialize(d, &major, &minor)) {
          ++eglDisplayUsers()[d];
          display_ = d;
          platform_ = device ? "device" : "surfaceless";
          return;
        }
        eglDisplayUsers().erase(d);
        why = std::string(device ? "device" : "surfaceless") + ": eglInitialize failed: " + lastError();
      }
      reasons += (reasons.empty() ? "" : "; ") + why;
    }
    throw Error("EGL backend: no usable display (" + reasons +
                "); install libegl-mesa0 (and libgl1-mesa-dri for llvmpipe) or set SNELL_GL_BACKEND=osmesa");
  }

  void releaseDisplay() {
    std::lock_guard<std::mutex> lock(eglDisplayMutex());
    auto it = eglDisplayUsers().find(display_);
    if (it != eglDisplayUsers().end() && --it->second == 0) {
      egl_.Terminate(display_);
      eglDisplayUsers().erase(it);
    }
    display_ = EGL_NO_DISPLAY;
  }

  void createContext() {
    const char* exts = egl_.QueryString(display_, EGL_EXTENSIONS);
    if (!hasExtension(exts, "EGL_KHR_no_config_context") && !hasExtension(exts, "EGL_MESA_configless_context"))
      throw Error("EGL backend (" + platform_ + "): display lacks EGL_KHR_no_config_context; upgrade Mesa/the driver");
    if (!hasExtension(exts, "EGL_KHR_surfaceless_context"))
      throw Error("EGL backend (" + platform_ + "): display lacks EGL_KHR_surfaceless_context; upgrade Mesa/the driver");
    if (!egl_.BindAPI(EGL_OPENGL_API))
      throw Error("EGL backend (" + platform_ + "): eglBindAPI(EGL_OPENGL_API) failed (" + lastError() +
                  "); the EGL driver offers no desktop OpenGL");
    // 4.5 first; 4.3 is the floor (compute shaders, SSBOs).
    for (int minor : {5, 3}) {
      const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, minor,
                                EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
      context_ = egl_.CreateContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
      if (context_ != EGL_NO_CONTEXT) return;
    }
    throw Error("EGL backend (" + platform_ + "): eglCreateContext failed for OpenGL 4.3+ core (" + lastError() +
                "); the driver is too old or set SNELL_GL_BACKEND=osmesa");
  }
};

inline std::unique_ptr<BackendContext> createEglContext() { return std::make_unique<EglContext>(); }

}  // namespace snell::gpu::detail
