// The one translation unit holding stb_image's (PNG-only) implementation.
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#define STBI_NO_STDIO_HDR
#define STB_IMAGE_IMPLEMENTATION
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

#include <algorithm>
#include <cstdint>
#include <memory>

#include "io/atomic_file.hpp"
#include "io/png.hpp"

namespace tumble::io {

Image read_png(const std::filesystem::path& path, ReadRole role) {
  const std::string bytes = read_input_file(path, kMaxPngBytes, "PNG file", role);
  const auto* p = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int len = static_cast<int>(std::min<std::size_t>(bytes.size(), INT32_MAX));
  int w = 0, h = 0, channels = 0;
  if (!stbi_info_from_memory(p, len, &w, &h, &channels)) throw IoError("cannot read PNG " + path.string() + ": not a PNG image");
  if (static_cast<long long>(w) * h > kMaxPngPixels)
    throw IoError("cannot read PNG " + path.string() + ": " + std::to_string(w) + "x" + std::to_string(h) +
                  " pixels, more than the cap of " + std::to_string(kMaxPngPixels));
  const std::unique_ptr<stbi_uc, void (*)(void*)> data(stbi_load_from_memory(p, len, &w, &h, &channels, 3),
                                                       stbi_image_free);
  if (!data) {
    // stbi_failure_reason uses a global; the message is only a hint anyway.
    throw IoError("cannot read PNG " + path.string());
  }
  const std::size_t n = static_cast<std::size_t>(w) * h * 3;
  return Image{w, h, std::vector<std::uint8_t>(data.get(), data.get() + n)};
}

}  // namespace tumble::io
