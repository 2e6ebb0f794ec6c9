// The one exception type of the GPU layer. Every failure (no library, no
// context, GL error, compile error, bad #include) is reported as an Error whose
// message says what is missing and, where there is one, how to fix it.
#pragma once

#include <stdexcept>

namespace snell::gpu {

struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace snell::gpu
