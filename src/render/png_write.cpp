// The one translation unit holding stb_image_write's implementation.
#include <libdeflate.h>

#include <cstdlib>
#include <memory>

namespace {

// Level 2 of libdeflate is ~4x faster than stb's deflate and still smaller.
constexpr int kDeflateLevel = 2;

struct CompressorDeleter {
  void operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }
};

// stb calls this from whichever thread encodes; one compressor per thread
// avoids both locking and re-allocating the compressor's tables per frame.
unsigned char* tumble_zlib_compress(unsigned char* data, int data_len, int* out_len,
                                    int /*stb_quality*/) {
  thread_local std::unique_ptr<libdeflate_compressor, CompressorDeleter> compressor(
      libdeflate_alloc_compressor(kDeflateLevel));
  if (!compressor || data_len < 0) return nullptr;
  const std::size_t bound =
      libdeflate_zlib_compress_bound(compressor.get(), static_cast<std::size_t>(data_len));
  // stb releases the result with STBIW_FREE (free), so it must come from malloc.
  auto* out = static_cast<unsigned char*>(std::malloc(bound));
  if (out == nullptr) return nullptr;
  const std::size_t n = libdeflate_zlib_compress(compressor.get(), data,
                                                 static_cast<std::size_t>(data_len), out, bound);
  if (n == 0) {
    std::free(out);
    return nullptr;
  }
  *out_len = static_cast<int>(n);
  return out;
}

}  // namespace

#define STBIW_ZLIB_COMPRESS tumble_zlib_compress
#define STBIW_CRC32(buffer, len) libdeflate_crc32(0, buffer, static_cast<std::size_t>(len))
#define STB_IMAGE_WRITE_STATIC  // keep stb's symbols (and its globals) private to this file
#define STB_IMAGE_WRITE_IMPLEMENTATION
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

#include <unistd.h>

#include <cstdio>
#include <mutex>
#include <stdexcept>
#include <string>
#include <system_error>

#include "render/png_io.hpp"

namespace tumble::render {
namespace {

// stb's filter override is a file-level global; it is set exactly once, before
// the first encode, and only read afterwards. The Up filter (2) is the
// cheapest one that still compresses smooth renders well.
constexpr int kPngFilter = 2;
std::once_flag g_filter_once;

struct MallocDeleter {
  void operator()(unsigned char* p) const { STBIW_FREE(p); }
};

}  // namespace

std::vector<std::uint8_t> encode_png(const Image& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgb.size() != static_cast<std::size_t>(image.width) * image.height * 3) {
    throw std::invalid_argument("encode_png: image size does not match its pixel buffer");
  }
  std::call_once(g_filter_once, [] { stbi_write_force_png_filter = kPngFilter; });
  int len = 0;
  const std::unique_ptr<unsigned char, MallocDeleter> png(stbi_write_png_to_mem(
      image.rgb.data(), image.width * 3, image.width, image.height, 3, &len));
  if (!png) throw std::runtime_error("encode_png: PNG compression failed");
  return {png.get(), png.get() + len};
}

void write_png_atomic(const std::filesystem::path& path, const Image& image) {
  std::filesystem::path tmp = path;
  tmp += ".tmp." + std::to_string(::getpid());
  try {
    const std::vector<std::uint8_t> bytes = encode_png(image);
    std::FILE* f = std::fopen(tmp.c_str(), "wb");
    if (f == nullptr) throw std::system_error(errno, std::generic_category(), "open");
    const bool wrote = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
    const int write_errno = errno;
    if (std::fclose(f) != 0 || !wrote) {
      throw std::system_error(wrote ? errno : write_errno, std::generic_category(), "write");
    }
    std::filesystem::rename(tmp, path);
  } catch (const std::exception& e) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw std::runtime_error("cannot write PNG " + path.string() + ": " + e.what());
  }
}

}  // namespace tumble::render
