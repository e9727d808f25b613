// A frame in memory: top-down rows, tightly packed RGB8.
#pragma once

#include <cstdint>
#include <vector>

namespace tumble::io {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  ///< width * height * 3 bytes, row 0 = top

  const std::uint8_t* pixel(int x, int y) const {
    return rgb.data() + (static_cast<std::size_t>(y) * width + x) * 3;
  }
};

}  // namespace tumble::io
