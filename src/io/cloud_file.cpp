#include "io/cloud_file.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>
#include <string_view>
#include <vector>

#include "base/error.hpp"
#include "base/input_file.hpp"
#include "base/quote.hpp"

namespace tumble::io {

namespace {

// Splits on blanks; std::from_chars keeps parsing locale-independent and strict.
bool parse_double(std::string_view tok, double& out) {
  const char* end = tok.data() + tok.size();
  auto [ptr, ec] = std::from_chars(tok.data(), end, out);
  return ec == std::errc() && ptr == end;
}

}  // namespace

namespace {

std::vector<std::string> split_fields(const std::string& line, bool csv) {
  std::vector<std::string> tok;
  if (!csv) {
    std::istringstream fields(line);
    for (std::string t; fields >> t;) tok.push_back(t);
    return tok;
  }
  std::istringstream fields(line);
  for (std::string t; std::getline(fields, t, ',');) {
    const auto b = t.find_first_not_of(" \t\r"), e = t.find_last_not_of(" \t\r");
    tok.push_back(b == std::string::npos ? "" : t.substr(b, e - b + 1));
  }
  if (!line.empty() && line.back() == ',') tok.push_back("");
  return tok;
}

// A header names x, y, z and m once each (any order, any case); other columns are ignored.
bool read_header(const std::vector<std::string>& tok, std::vector<int>& column, std::string& why) {
  double dummy;
  if (std::any_of(tok.begin(), tok.end(), [&](const std::string& t) { return parse_double(t, dummy); })) return false;
  column.assign(4, -1);
  for (std::size_t i = 0; i < tok.size(); ++i) {
    std::string name = tok[i];
    for (char& ch : name) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    const auto k = std::string_view("xyzm").find(name.size() == 1 ? name[0] : '?');
    if (k == std::string_view::npos) continue;
    if (column[k] >= 0) why = "column " + quote_token(tok[i], '\'') + " appears twice";
    column[k] = static_cast<int>(i);
  }
  for (int k = 0; k < 4 && why.empty(); ++k)
    if (column[static_cast<std::size_t>(k)] < 0) why = std::string("no column named '") + "xyzm"[k] + "'";
  return true;
}

}  // namespace

ParticleCloud parse_cloud_text(const std::string& text, const std::string& source_name) {
  ParticleCloud cloud;
  // Excel's "CSV UTF-8" export starts with a byte-order mark: not part of the header.
  constexpr std::string_view kBom = "\xEF\xBB\xBF";
  std::istringstream in(text.rfind(kBom, 0) == 0 ? text.substr(kBom.size()) : text);
  std::string line;
  int line_no = 0;
  bool first = true, csv = false;
  std::vector<int> column = {0, 1, 2, 3};
  std::size_t fields = 4;
  while (std::getline(in, line)) {
    ++line_no;
    if (auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    auto where = [&] { return source_name + ":" + std::to_string(line_no) + ": "; };
    if (first) {  // the first data line decides: commas make it CSV, names make it a header
      first = false;
      csv = line.find(',') != std::string::npos;
      const std::vector<std::string> head = split_fields(line, csv);
      std::string why;
      if (read_header(head, column, why)) {
        if (!why.empty()) throw InputError(where() + "header: " + why + "; expected columns x, y, z, m in any order");
        fields = head.size();
        continue;
      }
    }
    const std::vector<std::string> tok = split_fields(line, csv);
    if (tok.size() != fields)
      throw InputError(where() + "expected " + std::to_string(fields) +
                       (fields == 4 && column[3] == 3 ? " numbers `x y z m` (m, kg)" : " fields, as in the header") +
                       ", found " + std::to_string(tok.size()) + " fields");
    double v[4];
    for (int i = 0; i < 4; ++i) {
      const std::string& t = tok[static_cast<std::size_t>(column[static_cast<std::size_t>(i)])];
      if (!parse_double(t, v[i]))
        throw InputError(where() + "expected a number, found " + quote_token(t, '\''));
      if (!std::isfinite(v[i]))
        throw InputError(where() + "expected a finite number, found " + quote_token(t, '\''));
    }
    if (!(v[3] > 0.0))
      throw InputError(where() + "particle mass must be > 0 kg, found " + quote_token(tok[static_cast<std::size_t>(column[3])], '\''));
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

}  // namespace tumble::io
