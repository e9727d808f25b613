// A glyph atlas baked once with stb_truetype (ASCII, Latin-1, Greek, sub- and
// superscripts, arrows and math symbols, so labels like "ω₁ ≈ I₂ × ½" work)
// and the CPU-side layout of text into textured quads.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

namespace tumble::render {

struct TextVertex {
  glm::vec2 position_px;  ///< top-left origin
  glm::vec2 uv;
  glm::vec4 color;
};

class FontAtlas {
 public:
  /// Loads a TrueType file and packs its glyphs at `bake_px`; throws if the
  /// file cannot be read or the glyphs do not fit.
  explicit FontAtlas(const std::filesystem::path& ttf, float bake_px = 48.0f);

  int width() const { return width_; }
  int height() const { return height_; }
  /// Single-channel coverage, width * height bytes, row 0 = top.
  const std::vector<std::uint8_t>& pixels() const { return pixels_; }

  /// Appends two triangles per glyph of UTF-8 `text`. `top_left_px` is the
  /// top-left corner of the first line box; '\n' starts a new line.
  void layout(std::string_view text, glm::vec2 top_left_px, float size_px, glm::vec4 color,
              std::vector<TextVertex>& out) const;

  /// Two triangles filling `box_px` (x0, y0, x1, y1) with `color`: a backdrop
  /// drawn by the same pass as the glyphs, so it layers with them in order.
  void rect(glm::vec4 box_px, glm::vec4 color, std::vector<TextVertex>& out) const;

  /// Width and height in pixels of `text` at `size_px` (for alignment).
  glm::vec2 measure(std::string_view text, float size_px) const;

  /// The code points the atlas holds, ascending.
  std::vector<char32_t> code_points() const;

 private:
  struct Glyph {
    float x0, y0, x1, y1;  // quad relative to the pen at bake size
    float u0, v0, u1, v1;
    float advance;
  };
  const Glyph* find(char32_t c) const;

  int width_ = 1024, height_ = 2048;  // the first 1024 rows as before the atlas grew: the same glyph texels
  glm::vec2 solid_uv_{0};
  glm::vec2 texel_{0};  // one atlas texel in uv
  float bake_px_;
  float ascent_px_ = 0, line_px_ = 0;  // at bake size
  std::vector<std::uint8_t> pixels_;
  std::vector<std::pair<char32_t, Glyph>> glyphs_;  // sorted by code point
};

}  // namespace tumble::render
