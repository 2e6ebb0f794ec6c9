// What a GL backend (OSMesa, EGL) provides to snell::gpu::Context: a created
// context that can be bound to and released from the calling thread, and the
// backend's own GetProcAddress for filling the GlApi table.
#pragma once

#include "gl_api.hpp"

namespace snell::gpu::detail {

class BackendContext {
 public:
  virtual ~BackendContext() = default;
  BackendContext() = default;
  BackendContext(const BackendContext&) = delete;
  BackendContext& operator=(const BackendContext&) = delete;

  virtual void bind() = 0;    // make current on this thread; throws Error
  virtual void unbind() = 0;  // release from this thread; never throws
  virtual void* getProc(const char* name) const = 0;

  GlApi gl;
};

// The snell context current on this thread. The two backends share Mesa's GL
// dispatch (libglapi) but keep separate notions of "current": binding an
// OSMesa context does not tell EGL that its context lost the thread, so an
// implementation may treat a later eglMakeCurrent of the context it still
// believes current as a no-op. Releasing the previous owner explicitly keeps
// both in step (Mesa 22.3 happens to work without it; other versions need not).
inline BackendContext*& currentOnThisThread() {
  thread_local BackendContext* current = nullptr;
  return current;
}

}  // namespace snell::gpu::detail
