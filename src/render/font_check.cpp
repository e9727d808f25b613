#include "render/font_check.hpp"

#include <cstdint>
#include <map>
#include <stdexcept>
#include <vector>

namespace tumble::render {

namespace {

struct Bad : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Big-endian reads, each checked against the bytes it may use.
struct Bytes {
  std::string_view d;
  std::uint64_t begin = 0, end = 0;  ///< the span reads are confined to
  std::string where;
  void need(std::uint64_t at, std::uint64_t n) const {
    if (at < begin || at + n > end) throw Bad(where + " is cut short (reads byte " + std::to_string(at + n) +
                                              " of a span ending at " + std::to_string(end) + ")");
  }
  unsigned u8(std::uint64_t at) const {
    need(at, 1);
    return static_cast<unsigned char>(d[at]);
  }
  unsigned u16(std::uint64_t at) const {
    need(at, 2);
    return (u8(at) << 8) | u8(at + 1);
  }
  int s16(std::uint64_t at) const { return static_cast<std::int16_t>(u16(at)); }
  std::uint32_t u32(std::uint64_t at) const { return (std::uint32_t(u16(at)) << 16) | u16(at + 2); }
  Bytes sub(std::uint64_t at, std::uint64_t n, const std::string& name) const {
    need(at, n);
    return {d, at, at + n, name};
  }
};

struct Font {
  Bytes file;
  std::map<std::string, Bytes> tables;
  unsigned glyphs = 0;
  std::vector<std::uint32_t> loca;  ///< numGlyphs + 1 offsets into glyf
  const Bytes& table(const char* tag, std::uint64_t min_size) const {
    const auto it = tables.find(tag);
    if (it == tables.end()) throw Bad(std::string("the required table '") + tag + "' is missing");
    if (it->second.end - it->second.begin < min_size)
      throw Bad(std::string("table '") + tag + "' is " + std::to_string(it->second.end - it->second.begin) +
                " bytes, fewer than " + std::to_string(min_size));
    return it->second;
  }
};

void read_directory(Font& f) {
  const std::uint32_t version = f.file.u32(0);
  if (version != 0x00010000 && version != 0x74727565 /* 'true' */)
    throw Bad("not a TrueType font (it does not start with the sfnt version 1.0 or 'true')");
  const unsigned n = f.file.u16(4);
  for (unsigned i = 0; i < n; ++i) {
    const std::uint64_t rec = 12 + 16ull * i;
    const std::string tag(f.file.d.substr(f.file.sub(rec, 16, "the table directory").begin, 4));
    const std::uint64_t at = f.file.u32(rec + 8), len = f.file.u32(rec + 12);
    if (at + len > f.file.end)
      throw Bad("table '" + tag + "' (bytes " + std::to_string(at) + " to " + std::to_string(at + len) +
                ") ends past the end of the file (" + std::to_string(f.file.end) + " bytes)");
    f.tables.emplace(tag, Bytes{f.file.d, at, at + len, "table '" + tag + "'"});
  }
}

void read_metrics(Font& f) {
  const Bytes& head = f.table("head", 54);
  const Bytes& maxp = f.table("maxp", 6);
  const Bytes& hhea = f.table("hhea", 36);
  const Bytes& hmtx = f.table("hmtx", 0);
  f.glyphs = maxp.u16(maxp.begin + 4);
  if (f.glyphs == 0) throw Bad("maxp says the font has no glyphs");
  if (hhea.s16(hhea.begin + 4) - hhea.s16(hhea.begin + 6) <= 0)  // the pixel scale divides by it
    throw Bad("hhea's ascent is not above its descent");
  const unsigned long_metrics = hhea.u16(hhea.begin + 34);
  if (long_metrics == 0 || long_metrics > f.glyphs)
    throw Bad("hhea's numberOfHMetrics " + std::to_string(long_metrics) + " is not in 1.." + std::to_string(f.glyphs));
  hmtx.need(hmtx.begin, 4ull * long_metrics + 2ull * (f.glyphs - long_metrics));
  const unsigned format = head.u16(head.begin + 50);
  if (format > 1) throw Bad("head's indexToLocFormat is " + std::to_string(format) + ", not 0 or 1");
  const Bytes& loca = f.table("loca", 0);
  const Bytes& glyf = f.table("glyf", 0);
  for (unsigned g = 0; g <= f.glyphs; ++g) {
    const std::uint32_t at = format == 0 ? 2 * loca.u16(loca.begin + 2ull * g) : loca.u32(loca.begin + 4ull * g);
    if ((!f.loca.empty() && at < f.loca.back()) || at > glyf.end - glyf.begin)
      throw Bad("loca's entry for glyph " + std::to_string(g) + " points outside the glyf table");
    f.loca.push_back(at);
  }
}

/// A simple glyph's record: contours, instructions, flags and coordinates all inside it.
void check_simple(const Bytes& g, int contours) {
  std::uint64_t at = g.begin + 10;
  int last = -1;
  for (int c = 0; c < contours; ++c, at += 2) {
    const int end = static_cast<int>(g.u16(at));
    if (end < last) throw Bad(g.where + ": its contour ends go backwards");
    last = end;
  }
  const unsigned points = static_cast<unsigned>(last + 1);
  at += 2 + g.u16(at);  // instructions
  std::uint64_t xs = 0, ys = 0;
  for (unsigned p = 0; p < points;) {
    const unsigned flag = g.u8(at++);
    unsigned times = 1;
    if (flag & 8) times += g.u8(at++);
    const unsigned x = (flag & 2) ? 1 : (flag & 16) ? 0 : 2, y = (flag & 4) ? 1 : (flag & 32) ? 0 : 2;
    xs += std::uint64_t(x) * times;
    ys += std::uint64_t(y) * times;
    p += times;
  }
  g.need(at, xs + ys);
}

/// A composite glyph's components: each a glyph of the font, none its own
/// part (stb_truetype would recurse for ever) and none deeper than 32. `state`: 0 unchecked, 1 being
/// checked, 2 good.
void check_glyph(const Font& f, unsigned index, std::vector<char>& state, int depth = 0) {
  if (state[index] == 2) return;
  if (depth > 32) throw Bad("glyph " + std::to_string(index) + " ends a chain of components over 32 deep");
  if (state[index] == 1) throw Bad("glyph " + std::to_string(index) + " is a component of itself");
  state[index] = 1;
  const std::uint32_t a = f.loca[index], b = f.loca[index + 1];
  if (a == b) {  // no outline (a space)
    state[index] = 2;
    return;
  }
  const Bytes& glyf = f.tables.at("glyf");
  const Bytes g = glyf.sub(glyf.begin + a, b - a, "glyph " + std::to_string(index));
  const int contours = g.s16(g.begin);
  // The box sizes the glyph's bitmap: a reversed one gave a negative width.
  if (g.s16(g.begin + 2) > g.s16(g.begin + 6) || g.s16(g.begin + 4) > g.s16(g.begin + 8))
    throw Bad(g.where + " has a reversed bounding box");
  if (contours >= 0) {
    check_simple(g, contours);
    state[index] = 2;
    return;
  }
  std::uint64_t at = g.begin + 10;
  for (bool more = true; more;) {
    const unsigned flags = g.u16(at), component = g.u16(at + 2);
    if (component >= f.glyphs) throw Bad(g.where + " uses glyph " + std::to_string(component) + ", past the last");
    at += 4 + ((flags & 1) ? 4 : 2);                                           // arguments
    at += (flags & 8) ? 2 : (flags & 0x40) ? 4 : (flags & 0x80) ? 8 : 0;       // scale
    g.need(g.begin, at - g.begin);
    check_glyph(f, component, state, depth + 1);
    more = flags & 0x20;
  }
  state[index] = 2;
}

/// The Unicode subtables stb_truetype may pick, in the formats it reads.
void check_cmap(const Font& f) {
  const Bytes& cmap = f.table("cmap", 4);
  const unsigned n = cmap.u16(cmap.begin + 2);
  bool found = false;
  for (unsigned i = 0; i < n; ++i) {
    const std::uint64_t rec = cmap.begin + 4 + 8ull * i;
    const unsigned platform = cmap.u16(rec), encoding = cmap.u16(rec + 2);
    if (!(platform == 0 || (platform == 3 && (encoding == 1 || encoding == 10)))) continue;
    found = true;
    const std::uint64_t at = cmap.begin + cmap.u32(rec + 4);
    const unsigned format = cmap.u16(at);
    const std::string name = "cmap subtable " + std::to_string(i) + " (format " + std::to_string(format) + ")";
    if (format == 0) {
      cmap.need(at, 262);
    } else if (format == 6) {
      cmap.need(at, 10 + 2ull * cmap.u16(at + 8));
    } else if (format == 12 || format == 13) {
      cmap.need(at, 16 + 12ull * cmap.u32(at + 12));
    } else if (format == 4) {
      const Bytes s = cmap.sub(at, cmap.u16(at + 2), name);
      const unsigned seg2 = s.u16(at + 6), range = s.u16(at + 8), selector = s.u16(at + 10), shift = s.u16(at + 12);
      unsigned want_range = 2;  // 2 × the largest power of two ≤ segCount, as the spec sets it (stb searches by it)
      unsigned want_selector = 0;
      while (want_range * 2 <= seg2) want_range *= 2, ++want_selector;
      if (seg2 == 0 || seg2 % 2 || range != want_range || selector != want_selector || shift != seg2 - range)
        throw Bad(name + ": its search header does not match its segment count");
      s.need(at + 16, 4ull * seg2);  // endCode, pad, startCode, idDelta, idRangeOffset
      const std::uint64_t offsets = at + 16 + 3ull * seg2;
      for (unsigned k = 0; k < seg2 / 2; ++k) {
        const unsigned end = s.u16(at + 14 + 2ull * k), start = s.u16(at + 16 + seg2 + 2ull * k);
        const unsigned ro = s.u16(offsets + 2ull * k);
        if (ro != 0 && end >= start) s.need(offsets + 2ull * k + ro, 2ull * (end - start + 1));
      }
    } else {
      throw Bad(name + " is a format tumble's font reader does not read");
    }
  }
  if (!found) throw Bad("cmap has no Unicode subtable");
}

}  // namespace

std::string truetype_problem(std::string_view font) {
  try {
    Font f{Bytes{font, 0, font.size(), "the file"}, {}, 0, {}};
    read_directory(f);
    read_metrics(f);
    std::vector<char> state(f.glyphs, 0);
    for (unsigned g = 0; g < f.glyphs; ++g) check_glyph(f, g, state);
    check_cmap(f);
    return {};
  } catch (const Bad& e) {
    return e.what();
  }
}

}  // namespace tumble::render
