// PNG encode/decode for frames. Encoding uses stb_image_write with libdeflate
// as its zlib (several times faster than stb's own deflate).
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "io/image.hpp"

namespace tumble::io {

/// The PNG file bytes of an RGB image. Thread-safe. Throws on bad input.
std::vector<std::uint8_t> encode_png(const Image& image);

/// Encodes and writes through atomic_write_file (no fsync: see Durability),
/// so readers never see a half-written frame. Throws IoError naming the
/// path. Thread-safe for distinct paths.
void write_png_atomic(const std::filesystem::path& path, const Image& image);

/// Reads any 8-bit PNG as RGB. Throws IoError naming the path.
Image read_png(const std::filesystem::path& path);

}  // namespace tumble::io
