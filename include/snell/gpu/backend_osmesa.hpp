// OSMesa backend: Mesa's off-screen GL (llvmpipe), GL 4.5 core, no display.
// Mesa removed OSMesa in 25.1, hence the EGL backend next to it.
//
// <GL/osmesa.h> is deliberately not included: it pulls in <GL/gl.h> with its
// gl* prototypes, which clash with glcorearb.h and would invite direct calls.
// The handful of declarations needed are restated here from Mesa's osmesa.h.
#pragma once

#include "backend.hpp"
#include "dynamic_library.hpp"

#include <memory>
#include <string>
#include <vector>

namespace snell::gpu::detail {

namespace osmesa {
using ContextHandle = void*;  // OSMesaContext (struct osmesa_context*)
using Proc = void (*)();
using CreateContextAttribsFn = ContextHandle (*)(const int* attribs, ContextHandle share);
using MakeCurrentFn = GLboolean (*)(ContextHandle, void* buffer, GLenum type, GLsizei width, GLsizei height);
using DestroyContextFn = void (*)(ContextHandle);
using GetProcAddressFn = Proc (*)(const char*);

constexpr int kFormat = 0x22;  // OSMESA_FORMAT
constexpr int kRgba = 0x1908;  // OSMESA_RGBA (== GL_RGBA)
constexpr int kDepthBits = 0x30;
constexpr int kStencilBits = 0x31;
constexpr int kAccumBits = 0x32;
constexpr int kProfile = 0x33;
constexpr int kCoreProfile = 0x34;
constexpr int kContextMajorVersion = 0x36;
constexpr int kContextMinorVersion = 0x37;
}  // namespace osmesa

class OsmesaContext final : public BackendContext {
 public:
  OsmesaContext() {
    std::string why;
    lib_ = openLibrary({"libOSMesa.so.8", "libOSMesa.so"}, why);
    if (lib_.handle == nullptr)
      throw Error("OSMesa backend: cannot load libOSMesa.so.8 or libOSMesa.so (" + why +
                  "); install libosmesa6 (Debian/Ubuntu) or set SNELL_GL_BACKEND=egl");
    const char* b = "OSMesa";
    create_ = requireSymbol<osmesa::CreateContextAttribsFn>(lib_, "OSMesaCreateContextAttribs", b);
    makeCurrent_ = requireSymbol<osmesa::MakeCurrentFn>(lib_, "OSMesaMakeCurrent", b);
    destroy_ = requireSymbol<osmesa::DestroyContextFn>(lib_, "OSMesaDestroyContext", b);
    getProcAddress_ = requireSymbol<osmesa::GetProcAddressFn>(lib_, "OSMesaGetProcAddress", b);

    // All rendering goes to framebuffer objects; the default framebuffer only
    // has to exist, so it is tiny and has no depth.
    const int attribs[] = {osmesa::kFormat, osmesa::kRgba, osmesa::kDepthBits, 0,
                           osmesa::kStencilBits, 0, osmesa::kAccumBits, 0,
                           osmesa::kProfile, osmesa::kCoreProfile,
                           osmesa::kContextMajorVersion, 4, osmesa::kContextMinorVersion, 5, 0};
    context_ = create_(attribs, nullptr);
    if (context_ == nullptr)
      throw Error("OSMesa backend: OSMesaCreateContextAttribs failed for a 4.5 core profile (" + lib_.name +
                  " is too old or built without gallium llvmpipe); upgrade Mesa or set SNELL_GL_BACKEND=egl");
    buffer_.assign(static_cast<std::size_t>(kSize) * kSize * 4, 0);
  }

  ~OsmesaContext() override {
    if (currentOnThisThread() == this) {
      unbind();
      currentOnThisThread() = nullptr;
    }
    destroy_(context_);
  }

  void bind() override {
    if (!makeCurrent_(context_, buffer_.data(), GL_UNSIGNED_BYTE, kSize, kSize))
      throw Error("OSMesa backend: OSMesaMakeCurrent failed");
  }
  void unbind() override {
    if (gl.Finish) gl.Finish();
    // OSMesaMakeCurrent(NULL, NULL, ...) is Mesa's documented "release".
    makeCurrent_(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
  }
  void* getProc(const char* name) const override { return reinterpret_cast<void*>(getProcAddress_(name)); }

 private:
  static constexpr int kSize = 16;
  DynamicLibrary lib_;
  osmesa::CreateContextAttribsFn create_ = nullptr;
  osmesa::MakeCurrentFn makeCurrent_ = nullptr;
  osmesa::DestroyContextFn destroy_ = nullptr;
  osmesa::GetProcAddressFn getProcAddress_ = nullptr;
  osmesa::ContextHandle context_ = nullptr;
  std::vector<unsigned char> buffer_;  // the default framebuffer's storage, owned here
};

inline std::unique_ptr<BackendContext> createOsmesaContext() { return std::make_unique<OsmesaContext>(); }

}  // namespace snell::gpu::detail
