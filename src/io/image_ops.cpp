#include "io/image_ops.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

#define STB_IMAGE_RESIZE_STATIC  // stb's symbols private to this file
#define STB_IMAGE_RESIZE_IMPLEMENTATION
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wuseless-cast"
#include <stb/stb_image_resize.h>
#pragma GCC diagnostic pop

namespace tumble::io {

Image resized(const Image& image, int width, int height) {
  if (width <= 0 || height <= 0 || image.width <= 0 || image.height <= 0)
    throw std::invalid_argument("resized: empty size " + std::to_string(width) + "x" + std::to_string(height));
  if (width == image.width && height == image.height) return image;
  Image out{width, height, std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height * 3)};
  if (!stbir_resize_uint8_srgb(image.rgb.data(), image.width, image.height, 0, out.rgb.data(), width, height, 0, 3,
                               STBIR_ALPHA_CHANNEL_NONE, 0))
    throw std::invalid_argument("resized: stb_image_resize refused " + std::to_string(image.width) + "x" +
                                std::to_string(image.height) + " -> " + std::to_string(width) + "x" +
                                std::to_string(height));
  return out;
}

void paste(Image& into, const Image& part, int x, int y) {
  const int x0 = std::max(0, x), x1 = std::min(into.width, x + part.width);
  if (x1 <= x0) return;
  for (int row = std::max(0, y); row < std::min(into.height, y + part.height); ++row)
    std::memcpy(into.rgb.data() + (static_cast<std::size_t>(row) * into.width + x0) * 3,
                part.pixel(x0 - x, row - y), static_cast<std::size_t>(x1 - x0) * 3);
}

Image filled(int width, int height, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  Image out{width, height, {}};
  out.rgb.resize(static_cast<std::size_t>(std::max(0, width)) * std::max(0, height) * 3);
  for (std::size_t i = 0; i < out.rgb.size(); i += 3) out.rgb[i] = r, out.rgb[i + 1] = g, out.rgb[i + 2] = b;
  return out;
}

}  // namespace tumble::io
