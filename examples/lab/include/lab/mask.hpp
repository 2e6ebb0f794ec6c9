// A per-pixel boolean mask (which pixels see the refractive object), in the
// same row order as snell::Image (row 0 at the bottom).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace snell::lab {

struct Mask {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> bits;  // 0 or 1

  Mask() = default;
  Mask(int w, int h) : width(w), height(h), bits(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0) {}
  bool at(int x, int y) const { return bits[index(x, y)] != 0; }
  void set(int x, int y, bool v) { bits[index(x, y)] = v ? 1 : 0; }
  std::size_t count() const {
    std::size_t n = 0;
    for (std::uint8_t b : bits) n += b;
    return n;
  }

 private:
  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
  }
};

}  // namespace snell::lab
