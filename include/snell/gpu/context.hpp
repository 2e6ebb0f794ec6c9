// A headless OpenGL 4.3+ core context on the CPU (Mesa llvmpipe) or a GPU,
// through OSMesa or EGL, chosen at run time. Both libraries are dlopen()ed, so
// the binary links neither and both backends can coexist in one process.
//
//   snell::gpu::Context ctx;                 // SNELL_GL_BACKEND, else OSMesa, else EGL
//   const snell::gpu::GlApi& gl = ctx.gl();  // every GL call goes through this table
//
// One context is current per thread. Creating a Context makes it current;
// with several contexts call makeCurrent() before using another one.
#pragma once

#include "backend.hpp"
#include "backend_egl.hpp"
#include "backend_osmesa.hpp"
#include "error.hpp"
#include "gl_api.hpp"

#include <cctype>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>

namespace snell::gpu {

enum class Backend { Auto, OSMesa, EGL };

inline const char* backendName(Backend b) {
  switch (b) {
    case Backend::OSMesa: return "osmesa";
    case Backend::EGL: return "egl";
    case Backend::Auto:
    default: return "auto";
  }
}

// Every GL backend, in the order Auto tries them: the one list tests and tools
// iterate ("on every backend").
inline constexpr Backend kGlBackends[] = {Backend::OSMesa, Backend::EGL};

// A gtest parameter name generator for a Backend ("osmesa", "egl").
struct BackendParamName {
  template <class ParamInfo>
  std::string operator()(const ParamInfo& info) const {
    return backendName(info.param);
  }
};

// Case-insensitive inverse of backendName, for flags and SNELL_GL_BACKEND.
inline Backend parseBackend(const std::string& name) {
  std::string s;
  for (char c : name) s += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (s == "auto") return Backend::Auto;
  if (s == "osmesa") return Backend::OSMesa;
  if (s == "egl") return Backend::EGL;
  throw std::invalid_argument("unknown GL backend '" + name + "'; valid names: auto, osmesa, egl");
}

class Context {
 public:
  // Auto: SNELL_GL_BACKEND if set, else OSMesa if it works, else EGL.
  explicit Context(Backend backend = Backend::Auto) {
    if (backend == Backend::Auto) backend = backendFromEnvironment();
    if (backend != Backend::Auto) {
      create(backend);
      return;
    }
    // Auto: OSMesa first (the long-standing default on Debian 12), EGL second.
    std::string osmesaWhy;
    try {
      create(Backend::OSMesa);
      return;
    } catch (const Error& e) {
      osmesaWhy = e.what();
    }
    try {
      create(Backend::EGL);
    } catch (const Error& e) {
      throw Error("no GL context: tried OSMesa, then EGL.\n  " + osmesaWhy + "\n  " + e.what());
    }
  }

  ~Context() {
    // The backend destructor releases the thread if it owns it.
    impl_.reset();
  }
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;
  Context(Context&&) noexcept = default;
  Context& operator=(Context&&) noexcept = default;

  // The table lives on the heap with the backend context, so references (and
  // the GlApi references held by Program, Texture, ...) survive moves.
  const GlApi& gl() const { return impl().gl; }
  Backend backend() const { return backend_; }

  std::string renderer() const { return glString(GL_RENDERER); }
  std::string version() const { return glString(GL_VERSION); }

  void makeCurrent() const {
    detail::BackendContext* self = &impl();
    detail::BackendContext*& current = detail::currentOnThisThread();
    if (current != nullptr && current != self) current->unbind();
    current = nullptr;
    self->bind();
    current = self;
  }

 private:
  std::unique_ptr<detail::BackendContext> impl_;
  Backend backend_ = Backend::Auto;

  detail::BackendContext& impl() const {
    if (!impl_) throw Error("snell::gpu::Context: used after being moved from");
    return *impl_;
  }

  static Backend backendFromEnvironment() {
    const char* env = std::getenv("SNELL_GL_BACKEND");
    if (env == nullptr || *env == '\0') return Backend::Auto;
    try {
      return parseBackend(env);
    } catch (const std::invalid_argument& e) {
      throw Error(std::string("SNELL_GL_BACKEND: ") + e.what());
    }
  }

  void create(Backend backend) {
    impl_ = backend == Backend::OSMesa ? detail::createOsmesaContext() : detail::createEglContext();
    backend_ = backend;
    makeCurrent();
    const detail::BackendContext* b = impl_.get();
    impl_->gl = GlApi::loadWith([b](const char* name) { return b->getProc(name); });
    verifyVersion();
  }

  std::string glString(GLenum name) const {
    makeCurrentIfNeeded();
    const GLubyte* s = gl().GetString(name);
    return s ? reinterpret_cast<const char*>(s) : std::string();
  }
  void makeCurrentIfNeeded() const {
    if (detail::currentOnThisThread() != impl_.get()) makeCurrent();
  }

  // A context that reports no version is the symptom of the symbol clash
  // (DESIGN.md sec. 3); one below 4.3 cannot run compute shaders.
  void verifyVersion() const {
    const GLubyte* v = impl_->gl.GetString(GL_VERSION);
    const std::string who = std::string(backendName(backend_)) + " backend: ";
    if (v == nullptr)
      throw Error(who + "glGetString(GL_VERSION) returned NULL; the context is not current or GL entry points "
                        "resolve to another library");
    const char* s = reinterpret_cast<const char*>(v);
    int major = 0, minor = 0;
    char* end = nullptr;
    major = static_cast<int>(std::strtol(s, &end, 10));
    if (end && *end == '.') minor = static_cast<int>(std::strtol(end + 1, nullptr, 10));
    if (major < 4 || (major == 4 && minor < 3))
      throw Error(who + "OpenGL " + s + " is below 4.3 (compute shaders and SSBOs needed); upgrade Mesa/the driver");
  }
};

}  // namespace snell::gpu
