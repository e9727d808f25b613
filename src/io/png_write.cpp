// The one translation unit holding stb_image_write's implementation.
#include <libdeflate.h>

#include <cstdlib>
#include <cstring>
#include <memory>

namespace {

// Level 1 of libdeflate is ~3x faster than stb's deflate at a smaller size.
constexpr int kDeflateLevel = 1;

// Per-thread reusable blocks for the two frame-sized buffers stb allocates on
// every encode (the filtered rows and the zlib output). Fresh multi-MB
// mallocs are returned to the OS on free and page-faulted back in on the next
// frame, which costs more than the compression itself (~7 ms at 720p).
class ScratchBlocks {
 public:
  ~ScratchBlocks() {
    for (Slot& s : slots_) std::free(s.ptr);
  }
  void* allocate(std::size_t n) {
    if (n >= kMinSize) {
      for (Slot& s : slots_) {
        if (s.in_use) continue;
        if (s.capacity < n) {
          std::free(s.ptr);
          s.ptr = std::malloc(n);
          s.capacity = s.ptr ? n : 0;
          if (!s.ptr) return nullptr;
        }
        s.in_use = true;
        return s.ptr;
      }
    }
    return std::malloc(n);
  }
  void release(void* p) {
    if (Slot* s = find(p)) {
      s->in_use = false;
    } else {
      std::free(p);
    }
  }
  void* reallocate(void* p, std::size_t n) {
    Slot* s = find(p);
    if (s == nullptr) return std::realloc(p, n);
    if (n <= s->capacity) return p;
    void* q = std::malloc(n);
    if (q != nullptr) {
      std::memcpy(q, p, s->capacity);
      s->in_use = false;
    }
    return q;
  }

 private:
  static constexpr std::size_t kMinSize = 64 * 1024;
  struct Slot {
    void* ptr = nullptr;
    std::size_t capacity = 0;
    bool in_use = false;
  };
  Slot* find(void* p) {
    for (Slot& s : slots_) {
      if (p != nullptr && s.ptr == p) return &s;
    }
    return nullptr;
  }
  Slot slots_[2];
};

ScratchBlocks& scratch() {
  thread_local ScratchBlocks blocks;
  return blocks;
}

void* scratch_malloc(std::size_t n) { return scratch().allocate(n); }
void scratch_free(void* p) { scratch().release(p); }
// Only needed to satisfy stb's "all three or none" allocator rule.
[[maybe_unused]] void* scratch_realloc(void* p, std::size_t n) { return scratch().reallocate(p, n); }

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
  // stb releases the result with STBIW_FREE, so it comes from the same allocator.
  auto* out = static_cast<unsigned char*>(scratch_malloc(bound));
  if (out == nullptr) return nullptr;
  const std::size_t n = libdeflate_zlib_compress(compressor.get(), data,
                                                 static_cast<std::size_t>(data_len), out, bound);
  if (n == 0) {
    scratch_free(out);
    return nullptr;
  }
  *out_len = static_cast<int>(n);
  return out;
}

}  // namespace

#define STBIW_MALLOC(n) scratch_malloc(n)
#define STBIW_FREE(p) scratch_free(p)
#define STBIW_REALLOC(p, n) scratch_realloc(p, n)
#define STBIW_ZLIB_COMPRESS tumble_zlib_compress
#define STBIW_CRC32(buffer, len) libdeflate_crc32(0, buffer, static_cast<std::size_t>(len))
#define STB_IMAGE_WRITE_STATIC  // keep stb's symbols (and its globals) private to this file
#define STB_IMAGE_WRITE_IMPLEMENTATION
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

#include <mutex>
#include <stdexcept>
#include <string_view>

#include "io/atomic_file.hpp"
#include "io/png.hpp"

namespace tumble::io {
namespace {

// stb's filter override is a file-level global; it is set exactly once, before
// the first encode, and only read afterwards. Filter None (0) is both the
// fastest and, on our flat-shaded frames, the smallest (measured against
// Sub/Up/Average/Paeth and stb's per-row heuristic, which is ~4x slower).
constexpr int kPngFilter = 0;
std::once_flag g_filter_once;

std::string_view as_chars(const std::vector<std::uint8_t>& bytes) {
  return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
}

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
  atomic_write_file(path, as_chars(encode_png(image)), Durability::rename_only);
}

}  // namespace tumble::io
