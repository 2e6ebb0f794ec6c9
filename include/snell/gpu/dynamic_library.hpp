// Run-time loading of the GL backends (libOSMesa, libEGL) with dlopen.
//
// Why not link them: a binary that links libGL/libOpenGL and libOSMesa gets
// whichever gl* symbols the dynamic linker binds first (DESIGN.md sec. 3).
// Loading both with RTLD_LOCAL keeps their symbols out of the global namespace,
// lets one process hold contexts of both backends, and lets a machine without
// one of them still build and run with the other.
#pragma once

#include "error.hpp"

#include <dlfcn.h>

#include <initializer_list>
#include <string>

namespace snell::gpu::detail {

struct DynamicLibrary {
  void* handle = nullptr;
  std::string name;  // the soname that loaded
};

// Tries each soname in order. On failure returns a null handle and sets
// `whyNot` to every dlerror text, so the caller can explain all attempts.
// Handles are never dlclose()d: Mesa registers atexit handlers and thread-local
// dispatch state that crash if the library is unmapped while the process runs,
// and dlopen is reference counted, so reopening per context costs nothing.
inline DynamicLibrary openLibrary(std::initializer_list<const char*> sonames, std::string& whyNot) {
  whyNot.clear();
  for (const char* soname : sonames) {
    if (void* h = dlopen(soname, RTLD_NOW | RTLD_LOCAL)) return DynamicLibrary{h, soname};
    const char* err = dlerror();
    whyNot += std::string(whyNot.empty() ? "" : "; ") + (err ? err : soname);
  }
  return DynamicLibrary{};
}

// dlsym into a typed function pointer; throws Error naming the symbol and library.
template <class Fn>
Fn requireSymbol(const DynamicLibrary& lib, const char* symbol, const char* backend) {
  void* p = dlsym(lib.handle, symbol);
  if (p == nullptr)
    throw Error(std::string(backend) + " backend: " + lib.name + " has no symbol " + symbol +
                "; the library is too old or not the Mesa one");
  return reinterpret_cast<Fn>(p);
}

}  // namespace snell::gpu::detail
