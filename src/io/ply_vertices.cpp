#include "io/ply_vertices.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <optional>
#include <string_view>

#include "base/error.hpp"
#include "base/input_file.hpp"
#include "base/format.hpp"
#include "io/mesh_file.hpp"

namespace tumble::io {

namespace {

constexpr std::size_t kMaxHeaderLine = 4096;  ///< characters; longer is not a PLY header

struct Type {
  std::string_view name, alias;  ///< PLY 1.0 name and its sized alias
  int size;                      ///< bytes in a binary file
  bool floating;
};
constexpr std::array<Type, 8> kTypes{{{"char", "int8", 1, false}, {"uchar", "uint8", 1, false},
                                      {"short", "int16", 2, false}, {"ushort", "uint16", 2, false},
                                      {"int", "int32", 4, false}, {"uint", "uint32", 4, false},
                                      {"float", "float32", 4, true}, {"double", "float64", 8, true}}};

enum class Format { ascii, little_endian, big_endian };

struct Property {
  std::string name;
  const Type* type = nullptr;
  const Type* count = nullptr;  ///< a list's length type; null for a scalar
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  int line = 0;
  std::vector<Property> properties;
};

struct Word {
  std::string_view text;
  int column;  ///< 1-based
};

bool space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

std::vector<Word> split(std::string_view line) {
  std::vector<Word> out;
  for (std::size_t i = 0; i < line.size();) {
    while (i < line.size() && space(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !space(line[i])) ++i;
    if (i > start) out.push_back({line.substr(start, i - start), int(start) + 1});
  }
  return out;
}

// 'text', shortened and with unprintable bytes shown as '?' (garbage stays readable).
std::string quote(std::string_view s) {
  std::string out = "'";
  for (char c : s.substr(0, 40)) out += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
  return out + (s.size() > 40 ? "...'" : "'");
}

class Header {
 public:
  Header(std::istream& in, std::string name, std::vector<std::string>& warnings);
  Format format = Format::ascii;
  std::vector<Element> elements;
  int lines = 0;  ///< header lines, `end_header` included

 private:
  [[noreturn]] void fail(int column, const std::string& what) const {
    throw InputError(name_ + ":" + std::to_string(lines) + ":" + std::to_string(column) + ": " + what);
  }
  bool next_line(std::string& out);
  const Type& type_at(const Word& w) const;
  /// The line's words are exactly n, as `form` shows them.
  void expect_words(const std::vector<Word>& w, const std::string& line, std::size_t n, const std::string& form) const;
  void read_format(const std::vector<Word>& w, const std::string& line);
  void read_element(const std::vector<Word>& w, const std::string& line);
  void read_property(const std::vector<Word>& w, const std::string& line);

  std::istream& in_;
  std::string name_;
};

// Reads up to '\n' (a '\r' before it is whitespace); false at the end of the file.
bool Header::next_line(std::string& out) {
  out.clear();
  ++lines;
  for (int c; (c = in_.get()) != EOF;) {
    if (c == '\n') return true;
    if (out.size() == kMaxHeaderLine)
      fail(1, "a header line longer than " + std::to_string(kMaxHeaderLine) + " characters; expected a PLY header");
    out.push_back(static_cast<char>(c));
  }
  return !out.empty();
}

const Type& Header::type_at(const Word& w) const {
  for (const Type& t : kTypes)
    if (w.text == t.name || w.text == t.alias) return t;
  fail(w.column, "expected a PLY type (char, uchar, short, ushort, int, uint, float, double, or int8, uint8, int16, "
                 "uint16, int32, uint32, float32, float64), found " + quote(w.text));
}

void Header::expect_words(const std::vector<Word>& w, const std::string& line, std::size_t n,
                          const std::string& form) const {
  if (w.size() < n) fail(int(line.size()) + 1, "expected '" + form + "'; the line ends early");
  if (w.size() > n) fail(w[n].column, "expected the end of the line after '" + form + "', found " + quote(w[n].text));
}

void Header::read_format(const std::vector<Word>& w, const std::string& line) {
  expect_words(w, line, 3, "format ascii|binary_little_endian|binary_big_endian 1.0");
  if (w[1].text == "ascii") format = Format::ascii;
  else if (w[1].text == "binary_little_endian") format = Format::little_endian;
  else if (w[1].text == "binary_big_endian") format = Format::big_endian;
  else fail(w[1].column, "expected ascii, binary_little_endian or binary_big_endian, found " + quote(w[1].text));
  if (w[2].text != "1.0") fail(w[2].column, "expected version 1.0, found " + quote(w[2].text));
}

void Header::read_element(const std::vector<Word>& w, const std::string& line) {
  expect_words(w, line, 3, "element <name> <count>");
  std::uint64_t n = 0;
  const std::string_view t = w[2].text;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), n);
  if (ec != std::errc() || end != t.data() + t.size())
    fail(w[2].column, "expected the element count (a whole number >= 0), found " + quote(t));
  elements.push_back({std::string(w[1].text), n, lines, {}});
}

void Header::read_property(const std::vector<Word>& w, const std::string& line) {
  if (elements.empty()) fail(w[0].column, "a 'property' line before any 'element' line");
  const bool list = w.size() > 1 && w[1].text == "list";
  expect_words(w, line, list ? 5 : 3, list ? "property list <count type> <item type> <name>" : "property <type> <name>");
  Property p;
  if (list) {
    p.count = &type_at(w[2]);
    if (p.count->floating) fail(w[2].column, "expected an integer type for the list's length, found " + quote(w[2].text));
  }
  const Word& n = w[list ? 4 : 2];
  p.type = &type_at(w[list ? 3 : 1]);
  p.name = n.text;
  for (const Property& q : elements.back().properties)
    if (q.name == p.name) fail(n.column, "property " + quote(n.text) + " is declared twice in this element");
  elements.back().properties.push_back(std::move(p));
}

Header::Header(std::istream& in, std::string name, std::vector<std::string>& warnings)
    : in_(in), name_(std::move(name)) {
  std::string line;
  const bool any = next_line(line);
  const std::vector<Word> first = split(line);
  if (!any || first.size() != 1 || first[0].text != "ply" || first[0].column != 1)
    fail(1, "expected 'ply' (the first line of a PLY file), found " + quote(line));
  bool has_format = false;
  for (;;) {
    if (!next_line(line)) fail(1, "the file ends before 'end_header'");
    const std::vector<Word> w = split(line);
    if (w.empty()) continue;
    const std::string_view key = w[0].text;
    if (key == "end_header") {
      expect_words(w, line, 1, "end_header");
      if (!has_format) fail(1, "expected a 'format' line before 'end_header'");
      return;
    }
    if (key == "comment" || key == "obj_info") continue;
    if (key == "format") {
      if (has_format) fail(w[0].column, "a second 'format' line");
      read_format(w, line);
      has_format = true;
    } else if (key == "element") {
      read_element(w, line);
    } else if (key == "property") {
      read_property(w, line);
    } else {
      warnings.push_back(name_ + ":" + std::to_string(lines) + ": " + quote(key) +
                         " is not a PLY header keyword (comment, obj_info, element, property, end_header); the line "
                         "was ignored");
    }
  }
}

template <class T>
double as(const unsigned char* b) {
  T x;
  std::memcpy(&x, b, sizeof x);
  return static_cast<double>(x);
}

enum class Read { ok, end, not_a_number };

// Successive values of the data section: whitespace-separated words (ascii) or
// packed scalars (binary, byte order as declared).
class Data {
 public:
  Data(std::istream& in, Format f, int header_lines) : in_(in), format_(f), line_(header_lines) {}

  Read next(const Type& t, double& v) {
    if (format_ == Format::ascii) return word(v);
    std::array<unsigned char, 8> b{};
    in_.read(reinterpret_cast<char*>(b.data()), t.size);
    if (in_.gcount() != t.size) return Read::end;
    if ((format_ == Format::big_endian) != (std::endian::native == std::endian::big))
      std::reverse(b.begin(), b.begin() + t.size);
    switch (&t - kTypes.data()) {
      case 0: v = as<std::int8_t>(b.data()); break;
      case 1: v = as<std::uint8_t>(b.data()); break;
      case 2: v = as<std::int16_t>(b.data()); break;
      case 3: v = as<std::uint16_t>(b.data()); break;
      case 4: v = as<std::int32_t>(b.data()); break;
      case 5: v = as<std::uint32_t>(b.data()); break;
      case 6: v = as<float>(b.data()); break;
      default: v = as<double>(b.data()); break;
    }
    return Read::ok;
  }

  /// Skips `n` values of type `t` (a list's items).
  Read skip(const Type& t, std::uint64_t n) {
    if (format_ != Format::ascii) {
      const auto bytes = static_cast<std::streamsize>(n * static_cast<std::uint64_t>(t.size));
      in_.ignore(bytes);
      return in_.gcount() == bytes ? Read::ok : Read::end;
    }
    double v;
    for (std::uint64_t k = 0; k < n; ++k)
      if (const Read r = word(v); r != Read::ok) return r;
    return Read::ok;
  }

  /// ":<line>:<col>" of the last ascii word ("" in a binary file), and the word.
  std::string at() const {
    return format_ == Format::ascii ? ":" + std::to_string(line_) + ":" + std::to_string(column_) : "";
  }
  const std::string& last_word() const { return word_; }

 private:
  Read word(double& v) {
    for (;;) {
      while (pos_ < text_.size() && space(text_[pos_])) ++pos_;
      if (pos_ < text_.size()) break;
      if (!std::getline(in_, text_)) return Read::end;
      ++line_;
      pos_ = 0;
    }
    const std::size_t start = pos_;
    while (pos_ < text_.size() && !space(text_[pos_])) ++pos_;
    word_ = text_.substr(start, pos_ - start);
    column_ = int(start) + 1;
    const char* b = word_.data() + (word_[0] == '+' ? 1 : 0);
    const char* e = word_.data() + word_.size();
    const auto [end, ec] = std::from_chars(b, e, v);
    if (ec == std::errc::result_out_of_range) v = std::strtod(word_.c_str(), nullptr);  // ±inf (refused later) or ~0
    else if (ec != std::errc()) return Read::not_a_number;
    return end == e ? Read::ok : Read::not_a_number;
  }

  std::istream& in_;
  Format format_;
  std::string text_, word_;
  std::size_t pos_ = 0;
  int line_ = 0, column_ = 0;
};

// Reads record `i` of `e`; scalar values go to `values` (by property index) when given.
// With `vertices` > 0, every list entry must be a vertex index below it (faces).
void read_record(Data& d, const Element& e, std::uint64_t i, const std::string& name, std::vector<double>* values,
                 std::uint64_t vertices = 0, bool after_vertices = false) {
  auto record = [&] {  // built only for a message
    return e.name == "vertex" ? "vertex " + std::to_string(i)
                              : "element " + quote(e.name) + " record " + std::to_string(i) +
                                    (after_vertices ? "" : " (before the vertices)");
  };
  auto check = [&](Read r, const Property& p) {
    if (r == Read::end)
      throw InputError(name + ": the data ends inside " + record() + " of " + std::to_string(e.count) +
                       " (a truncated file?)");
    if (r == Read::not_a_number)
      throw InputError(name + d.at() + ": " + record() + ": expected a number for property " + quote(p.name) +
                       ", found " + quote(d.last_word()));
  };
  auto get = [&](const Type& t, const Property& p) {
    double v = 0;
    check(d.next(t, v), p);
    return v;
  };
  for (std::size_t k = 0; k < e.properties.size(); ++k) {
    const Property& p = e.properties[k];
    if (!p.count) {
      const double v = get(*p.type, p);
      if (values) (*values)[k] = v;
      continue;
    }
    const double n = get(*p.count, p);
    if (!(n >= 0 && n <= 0x1p53 && n == std::floor(n)))
      throw InputError(name + d.at() + ": " + record() + ": list " + quote(p.name) + " has length " + format_number(n, 6) +
                       "; expected a whole number >= 0");
    if (!vertices) {
      check(d.skip(*p.type, static_cast<std::uint64_t>(n)), p);
      continue;
    }
    for (std::uint64_t k2 = 0; k2 < static_cast<std::uint64_t>(n); ++k2) {
      const double v = get(*p.type, p);
      if (!(v >= 0 && v < static_cast<double>(vertices) && v == std::floor(v)))
        throw InputError(name + d.at() + ": " + record() + ": list " + quote(p.name) + " holds " + format_number(v, 6) +
                         "; expected a vertex index in [0, " + std::to_string(vertices) + ")");
    }
  }
}

PlyVertices read_ply(std::istream& in, const std::string& name, bool whole) {
  PlyVertices out;
  const Header h(in, name, out.warnings);
  const auto vertex = std::find_if(h.elements.begin(), h.elements.end(), [](const Element& e) { return e.name == "vertex"; });
  if (vertex == h.elements.end()) throw InputError(name + ": the header declares no 'vertex' element");
  for (const Element& e : h.elements)
    if (e.name == "face") out.faces += e.count;
  auto index = [&](const std::string& p, bool required) {
    const auto& ps = vertex->properties;
    const auto it = std::find_if(ps.begin(), ps.end(), [&](const Property& q) { return q.name == p; });
    const std::string where = name + ":" + std::to_string(vertex->line) + ": the vertex element ";
    if (it == ps.end() && required) throw InputError(where + "has no property '" + p + "'");
    if (it != ps.end() && it->count) throw InputError(where + "declares '" + p + "' as a list; expected a scalar");
    return it == ps.end() ? -1 : int(it - ps.begin());
  };
  const int x = index("x", true), y = index("y", true), z = index("z", true), mass = index("mass", false);
  if (vertex->count == 0) throw InputError(name + ":" + std::to_string(vertex->line) + ": the vertex element is empty");

  Data d(in, h.format, h.lines);
  for (auto e = h.elements.begin(); e != vertex; ++e)
    if (!e->properties.empty())
      for (std::uint64_t i = 0; i < e->count; ++i) read_record(d, *e, i, name, nullptr);
  std::vector<double> v(vertex->properties.size());
  out.positions.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(vertex->count, 1u << 20)));
  for (std::uint64_t i = 0; i < vertex->count; ++i) {
    read_record(d, *vertex, i, name, &v);
    const Eigen::Vector3d p(v[std::size_t(x)], v[std::size_t(y)], v[std::size_t(z)]);
    const std::string at = name + ": vertex " + std::to_string(i) + ": ";
    if (!p.allFinite()) throw InputError(at + "position (" + format_number(p.x(), 6) + ", " + format_number(p.y(), 6) + ", " + format_number(p.z(), 6) + ") is not finite");
    out.positions.push_back(p);
    if (mass < 0) continue;
    const double m = v[std::size_t(mass)];
    if (!std::isfinite(m)) throw InputError(at + "mass " + format_number(m, 6) + " is not finite");
    if (m < 0) throw InputError(at + "mass " + format_number(m, 6) + " kg is negative");
    out.masses.push_back(m);
  }
  // An element without properties holds no data whatever its count (up to 2^64 - 1): nothing to read.
  for (auto e = vertex + 1; whole && e != h.elements.end(); ++e)
    for (std::uint64_t i = 0; i < e->count && !e->properties.empty(); ++i)
      read_record(d, *e, i, name, nullptr, e->name == "face" ? vertex->count : 0, true);
  double total = 0;
  for (double m : out.masses) total += m;
  if (mass >= 0 && !(total > 0 && std::isfinite(total)))
    throw InputError(name + ": the vertex masses sum to " + format_number(total, 6) + " kg; expected a positive, finite total");
  return out;
}

}  // namespace

PlyVertices read_ply_vertices(std::istream& in, const std::string& name) { return read_ply(in, name, false); }

void check_ply_mesh(std::istream& in, const std::string& name) { (void)read_ply(in, name, true); }

PlyVertices read_ply_vertices(const std::filesystem::path& path) {
  std::string bytes;
  try {  // as every mesh: a regular file only, never waited on, under the mesh size cap
    bytes = read_input_file(path, kMaxMeshBytes, "PLY file");
  } catch (const UnreadableFile& e) {
    throw InputError(e.what());
  } catch (const InputError& e) {
    std::error_code ec;
    if (std::filesystem::exists(std::filesystem::symlink_status(path, ec))) throw;
    throw InputError(path.string() + ": cannot open the PLY file (paths are relative to the scene file)");
  }
  std::istringstream in(std::move(bytes));
  return read_ply_vertices(in, path.string());
}

bool is_ply_file(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".ply";
}

}  // namespace tumble::io
