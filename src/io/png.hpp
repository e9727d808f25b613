// PNG encode/decode for frames. Encoding uses stb_image_write with libdeflate
// as its zlib (several times faster than stb's own deflate).
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "base/input_file.hpp"
#include "io/image.hpp"

namespace tumble::io {

/// The PNG file bytes of an RGB image. Thread-safe. Throws on bad input.
std::vector<std::uint8_t> encode_png(const Image& image);

/// Encodes and writes through atomic_write_file (no fsync: see Durability),
/// so readers never see a half-written frame. Throws IoError naming the
/// path. Thread-safe for distinct paths.
void write_png_atomic(const std::filesystem::path& path, const Image& image);

/// Largest PNG file read (bytes) and decoded image (pixels): far beyond any
/// frame, so a crafted or mistaken file cannot fill memory.
inline constexpr std::size_t kMaxPngBytes = std::size_t(1) << 30;
inline constexpr long long kMaxPngPixels = 1LL << 26;

/// Reads any 8-bit PNG as RGB, a regular file only (base/input_file.hpp:
/// never blocks on a FIFO). Throws IoError naming the path, UnreadableFile
/// (not a regular file) or InputError (missing, over the caps).
Image read_png(const std::filesystem::path& path, ReadRole role = ReadRole::input);

}  // namespace tumble::io
