// PNG encode/decode for frames. Encoding uses stb_image_write with libdeflate
// as its zlib (several times faster than stb's own deflate).
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "render/image.hpp"

namespace tumble::render {

/// The PNG file bytes of an RGB image. Thread-safe. Throws on bad input.
std::vector<std::uint8_t> encode_png(const Image& image);

/// Writes `path.tmp.<pid>` then renames it onto `path`, so readers never see
/// a half-written frame. On failure the temp file is removed and a
/// std::runtime_error naming `path` is thrown. Thread-safe for distinct paths.
void write_png_atomic(const std::filesystem::path& path, const Image& image);

/// Reads any 8-bit PNG as RGB. Throws std::runtime_error naming the path.
Image read_png(const std::filesystem::path& path);

}  // namespace tumble::render
