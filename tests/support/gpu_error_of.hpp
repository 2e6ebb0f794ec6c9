// The message of the snell::gpu::Error a callable throws, for tests that check
// error texts; a different exception type, or none, is a test failure.
#pragma once

#include <gtest/gtest.h>

#include <snell/gpu/error.hpp>

#include <exception>
#include <string>

namespace snell_test {

template <class F>
std::string gpuErrorOf(F f) {
  try {
    f();
  } catch (const snell::gpu::Error& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "not a snell::gpu::Error: " << e.what();
    return e.what();
  }
  ADD_FAILURE() << "no exception thrown";
  return {};
}

}  // namespace snell_test
