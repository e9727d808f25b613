#include "core/particle_cloud.hpp"

#include <charconv>
#include <fstream>
#include <sstream>

#include "core/error.hpp"
#include "core/input_file.hpp"

namespace tumble {

void append_cloud(ParticleCloud& dst, const ParticleCloud& src, const Eigen::Vector3d& offset) {
  dst.reserve(dst.size() + src.size());
  for (const Particle& p : src) dst.push_back({p.position + offset, p.mass});
}

namespace {

// Splits on blanks; std::from_chars keeps parsing locale-independent and strict.
bool parse_double(std::string_view tok, double& out) {
  const char* end = tok.data() + tok.size();
  auto [ptr, ec] = std::from_chars(tok.data(), end, out);
  return ec == std::errc() && ptr == end;
}

}  // namespace

ParticleCloud parse_cloud_text(const std::string& text, const std::string& source_name) {
  ParticleCloud cloud;
  std::istringstream in(text);
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream fields(line);
    std::vector<std::string> tok;
    for (std::string t; fields >> t;) tok.push_back(t);
    if (tok.empty()) continue;
    auto where = [&] { return source_name + ":" + std::to_string(line_no) + ": "; };
    if (tok.size() != 4)
      throw InputError(where() + "expected 4 numbers `x y z m` (m, kg), found " +
                       std::to_string(tok.size()) + " fields");
    double v[4];
    for (int i = 0; i < 4; ++i) {
      if (!parse_double(tok[i], v[i]))
        throw InputError(where() + "expected a number, found '" + tok[i] + "'");
      if (!std::isfinite(v[i]))
        throw InputError(where() + "expected a finite number, found '" + tok[i] + "'");
    }
    if (!(v[3] > 0.0))
      throw InputError(where() + "particle mass must be > 0 kg, found " + tok[3]);
    cloud.push_back({Eigen::Vector3d(v[0], v[1], v[2]), v[3]});
  }
  return cloud;
}

ParticleCloud read_cloud_file(const std::filesystem::path& path, std::size_t max_bytes) {
  const std::string text = read_input_file(path, max_bytes, "cloud file");
  ParticleCloud c = parse_cloud_text(text, path.string());
  if (c.empty())
    throw InputError(path.string() + ": cloud file holds no particles (" +
                     (text.empty() ? std::string("it is empty") : "only comments and blank lines") +
                     "); expected one `x y z m` per line");
  return c;
}

}  // namespace tumble
