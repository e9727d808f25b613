#include "scene/mesh_precheck.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <vector>

#include "base/error.hpp"
#include "base/quote.hpp"
#include "scene/ply_vertices.hpp"

namespace tumble::scene {

namespace {

constexpr std::size_t kMaxLine = 1 << 16;  ///< characters in one line of a text mesh

// The lines of a text file, split into words, with their numbers for messages.
class Lines {
 public:
  Lines(std::string_view text, const std::string& name) : t_(text), name_(name) {
    if (t_.find('\0') != std::string_view::npos) fail("a NUL byte in a text mesh file (binary data?)");
  }
  bool next() {
    words.clear();
    if (pos_ >= t_.size()) return false;
    ++line_;
    std::size_t end = t_.find('\n', pos_);
    if (end == std::string_view::npos) end = t_.size();
    const std::string_view l = t_.substr(pos_, end - pos_);
    pos_ = end + 1;
    if (l.size() > kMaxLine) fail("a line longer than " + std::to_string(kMaxLine) + " characters");
    for (std::size_t i = 0; i < l.size();) {
      while (i < l.size() && std::isspace(static_cast<unsigned char>(l[i]))) ++i;
      const std::size_t b = i;
      while (i < l.size() && !std::isspace(static_cast<unsigned char>(l[i]))) ++i;
      if (i > b) words.push_back(l.substr(b, i - b));
    }
    return true;
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(name_ + ":" + std::to_string(line_) + ": " + what);
  }
  // A finite number at the start of the word (assimp reads "3.1+e2" as 3.1, as its own tests expect).
  double number(std::size_t k) const {
    if (k >= words.size()) fail("expected a number as word " + std::to_string(k + 1) + "; the line ends early");
    double v = 0;
    const std::string_view w = words[k].substr(words[k].size() > 1 && words[k][0] == '+' ? 1 : 0);
    const auto [p, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
    if (ec != std::errc() || p == w.data() || !std::isfinite(v))
      fail("expected a finite number, found " + quote_token(words[k], '\''));
    return v;
  }
  long long integer(std::string_view w) const {
    long long v = 0;
    const auto [p, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
    if (ec != std::errc() || p != w.data() + w.size()) fail("expected a whole number, found " + quote_token(w, '\''));
    return v;
  }
  std::vector<std::string_view> words;

 private:
  std::string_view t_;
  const std::string& name_;
  std::size_t pos_ = 0;
  int line_ = 0;
};

// Corners of one polygon: assimp's triangulation takes time quadratic in
// them (a face of 32 000 corners took some 10 s); 4096 stays under 0.2 s.
constexpr std::size_t kMaxFaceCorners = 4096;

std::string too_many_corners(std::size_t n) {
  return "a face of " + std::to_string(n) + " corners; tumble reads faces of at most " +
         std::to_string(kMaxFaceCorners) + " (triangulating one takes time quadratic in its corners): split it";
}

// v x y z [w]; f/l/p with 1-based (or negative, relative) vertex references.
void precheck_obj(std::string_view text, const std::string& name) {
  Lines in(text, name);
  long long vertices = 0;
  while (in.next()) {
    if (in.words.empty() || in.words[0][0] == '#') continue;
    const std::string_view k = in.words[0];
    if (k == "v") {
      for (std::size_t i = 1; i <= 3; ++i) (void)in.number(i);
      ++vertices;
    } else if (k == "f" || k == "l" || k == "p") {
      const std::size_t least = k == "f" ? 3 : k == "l" ? 2 : 1;
      if (in.words.size() < least + 1)
        in.fail("expected at least " + std::to_string(least) + " vertices after '" + std::string(k) + "'");
      if (in.words.size() - 1 > kMaxFaceCorners) in.fail(too_many_corners(in.words.size() - 1));
      for (std::size_t i = 1; i < in.words.size(); ++i) {
        const std::string_view w = in.words[i];
        const long long r = in.integer(w.substr(0, w.find('/')));
        if (r == 0 || r > vertices || -r > vertices)
          in.fail("vertex reference " + std::to_string(r) + "; expected 1.." + std::to_string(vertices) +
                  " (or -1..-" + std::to_string(vertices) + ", relative), the vertices defined so far");
      }
    }
  }
  if (vertices == 0) throw InputError(name + ": no 'v' lines: the OBJ file holds no vertices");
}

// OFF: a header line, "nv nf ne", nv lines "x y z ...", nf lines "n i1 .. in ...".
void precheck_off(std::string_view text, const std::string& name) {
  Lines in(text, name);
  auto content = [&] {
    while (in.next())
      if (!in.words.empty() && in.words[0][0] != '#') return true;
    return false;
  };
  if (!content() || in.words[0].find("OFF") == std::string_view::npos)
    in.fail("expected 'OFF' (the first line of an OFF file)");
  const std::size_t c = in.words.size() > 1 ? 1 : 0;  // the counts may follow OFF on its line
  if (c == 0 && !content()) in.fail("expected the counts line 'vertices faces edges'; the file ends");
  const long long nv = in.integer(in.words[c]);
  const long long nf = c + 1 < in.words.size() ? in.integer(in.words[c + 1]) : -1;
  if (nv < 1 || nf < 0) in.fail("expected counts 'vertices faces' (vertices >= 1, faces >= 0)");
  if (static_cast<double>(nv) * 6 + static_cast<double>(nf) * 8 > static_cast<double>(text.size()))
    in.fail("the counts need more bytes than the file's " + std::to_string(text.size()) + " (truncated or forged)");
  for (long long v = 0; v < nv; ++v) {
    if (!content()) throw InputError(name + ": the file ends after " + std::to_string(v) + " of " + std::to_string(nv) + " vertices");
    for (std::size_t i = 0; i < 3; ++i) (void)in.number(i);
  }
  for (long long f = 0; f < nf; ++f) {
    if (!content()) throw InputError(name + ": the file ends after " + std::to_string(f) + " of " + std::to_string(nf) + " faces");
    const long long n = in.integer(in.words[0]);
    if (n < 1 || static_cast<std::size_t>(n) + 1 > in.words.size())
      in.fail("face " + std::to_string(f) + ": expected " + quote_token(in.words[0], '\'') + " vertex indices after the count");
    if (static_cast<std::size_t>(n) > kMaxFaceCorners) in.fail("face " + std::to_string(f) + ": " + too_many_corners(n));
    for (long long i = 1; i <= n; ++i)
      if (const long long k = in.integer(in.words[static_cast<std::size_t>(i)]); k < 0 || k >= nv)
        in.fail("face " + std::to_string(f) + ": vertex index " + std::to_string(k) + "; expected 0.." + std::to_string(nv - 1));
  }
}

// Binary: 80-byte header, uint32 count, 50 bytes a triangle, nothing after.
// Text: "solid", then facet / outer loop / 3 × vertex x y z / endloop / endfacet.
void precheck_stl(std::string_view bytes, const std::string& name) {
  std::uint32_t n = 0;
  if (bytes.size() >= 84) std::memcpy(&n, bytes.data() + 80, 4);  // little-endian, as the format says
  const double binary_size = 84.0 + 50.0 * n;
  if (bytes.size() >= 84 && binary_size == static_cast<double>(bytes.size())) {
    if (n == 0) throw InputError(name + ": a binary STL of 0 triangles");
    return;
  }
  std::size_t lead = 0;
  while (lead < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[lead]))) ++lead;
  if (bytes.substr(lead, 5) != "solid" || bytes.substr(0, std::min<std::size_t>(bytes.size(), 1024)).find('\0') != std::string_view::npos)
    throw InputError(name + ": not an STL file: " + std::to_string(bytes.size()) + " bytes fit neither a binary STL (" +
                     (bytes.size() < 84 ? std::string("shorter than its 84-byte header")
                                        : "it declares " + std::to_string(n) + " triangles, which need " +
                                              std::to_string(static_cast<long long>(binary_size)) + " bytes") +
                     ") nor a text one (it starts with 'solid')");
  Lines in(bytes, name);
  long long corners = 0, facets = 0;
  while (in.next()) {
    if (in.words.empty()) continue;
    const std::string_view k = in.words[0];
    if (k == "vertex") {
      for (std::size_t i = 1; i <= 3; ++i) (void)in.number(i);
      ++corners;
    } else if (k == "facet") {
      ++facets;
    } else if (k == "endloop") {
      if (corners % 3 != 0) in.fail("a loop of " + std::to_string(corners % 3) + " vertices; expected 3 (a triangle)");
    } else if (k != "solid" && k != "outer" && k != "endfacet" && k != "endsolid") {
      in.fail("expected facet, outer loop, vertex, endloop, endfacet or endsolid, found " + quote_token(k, '\''));
    }
  }
  if (facets == 0 || corners != 3 * facets)
    throw InputError(name + ": a text STL of " + std::to_string(facets) + " facets and " + std::to_string(corners) +
                     " vertices; expected 3 vertices a facet, at least one facet");
}

}  // namespace

MeshFormat mesh_format(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == ".obj") return MeshFormat::obj;
  if (ext == ".stl") return MeshFormat::stl;
  if (ext == ".ply") return MeshFormat::ply;
  if (ext == ".off") return MeshFormat::off;
  throw InputError(path + ": expected a mesh file ending in .obj, .stl, .ply or .off (the formats checked before "
                          "import), found " + (ext.empty() ? std::string("no extension") : quote_token(ext, '\'')));
}

void precheck_mesh(std::string_view bytes, MeshFormat format, const std::string& name) {
  switch (format) {
    case MeshFormat::obj: return precheck_obj(bytes, name);
    case MeshFormat::off: return precheck_off(bytes, name);
    case MeshFormat::stl: return precheck_stl(bytes, name);
    case MeshFormat::ply: {
      std::istringstream in{std::string(bytes)};
      return check_ply_mesh(in, name);
    }
  }
}

}  // namespace tumble::scene
