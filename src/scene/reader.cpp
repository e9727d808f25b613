#include "scene/reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "base/quote.hpp"

namespace tumble::scene::detail {

namespace {

constexpr std::size_t kMaxErrors = 50;


std::string type_name(toml::node_type t) {
  switch (t) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a float";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::date: return "a date";
    case toml::node_type::time: return "a time";
    case toml::node_type::date_time: return "a date-time";
    default: return "nothing";
  }
}

}  // namespace

Diagnostic Diagnostics::make(const toml::source_region& at, std::string key, std::string message) const {
  Diagnostic dg;
  dg.file = file_;
  dg.line = !located_ ? 0 : at.begin.line ? static_cast<int>(at.begin.line) : 1;
  dg.column = !located_ ? 0 : at.begin.column ? static_cast<int>(at.begin.column) : 1;
  for (const auto& [k, option] : options_)
    if (k == key && !at.begin.line) dg.option = option;  // a value the file never held
  dg.key = std::move(key);
  dg.message = std::move(message);
  return dg;
}

void Diagnostics::error(const toml::source_region& at, std::string key, std::string message) {
  if (errors_.size() == kMaxErrors) {
    errors_.push_back(make(at, "", "too many errors; stopping here"));
    return;
  }
  if (errors_.size() > kMaxErrors) return;
  errors_.push_back(make(at, std::move(key), std::move(message)));
}

std::vector<Diagnostic> Diagnostics::take_errors() {
  const auto end = errors_.size() > kMaxErrors ? errors_.end() - 1 : errors_.end();
  std::stable_sort(errors_.begin(), end, [](const Diagnostic& a, const Diagnostic& b) {
    return a.line != b.line ? a.line < b.line : a.column < b.column;
  });
  return std::move(errors_);
}

void Diagnostics::warning(const toml::source_region& at, std::string key, std::string message) {
  const Diagnostic dg = make(at, std::move(key), std::move(message));
  const std::string where = dg.line ? dg.file + ":" + std::to_string(dg.line) + ":" + std::to_string(dg.column) : dg.file;
  warnings_.push_back(where + ": warning: " + dg.key + ": " + dg.message);
}

Range Range::closed(double lo, double hi) {
  return {lo, hi, false, "a number in [" + format_number(lo) + ", " + format_number(hi) + "]"};
}

bool Range::contains(double v) const {
  if (!std::isfinite(v)) return false;
  return (lo_open ? v > lo : v >= lo) && v <= hi;
}

std::string describe(const toml::node& n) {
  if (auto s = n.as_string()) return "the string " + quote_token(s->get());
  if (auto i = n.as_integer()) return std::to_string(i->get());
  if (auto f = n.as_floating_point()) return format_number(f->get());
  if (auto b = n.as_boolean()) return b->get() ? "true" : "false";
  if (auto a = n.as_array()) return "an array of " + std::to_string(a->size()) + " element(s)";
  return type_name(n.type());
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

std::string closest(std::string_view word, const std::vector<std::string_view>& candidates) {
  std::string best;
  std::size_t best_d = std::max<std::size_t>(2, (word.size() + 2) / 3) + 1;  // allow ~1 edit in 3
  for (std::string_view c : candidates) {
    const std::size_t d = edit_distance(word, c);
    if (d < best_d) best_d = d, best = std::string(c);
  }
  return best;
}

std::optional<double> read_number(const toml::node& n, const std::string& key, const Range& r, Diagnostics& d) {
  double v;
  if (auto i = n.as_integer()) v = static_cast<double>(i->get());
  else if (auto f = n.as_floating_point()) v = f->get();
  else {
    d.error(n.source(), key, "expected " + r.what + ", found " + describe(n));
    return std::nullopt;
  }
  if (!r.contains(v)) {
    d.error(n.source(), key, "expected " + r.what + ", found " + format_number(v));
    return std::nullopt;
  }
  return v;
}

TableReader::TableReader(const toml::table& t, std::string path, Diagnostics& d,
                         const std::vector<std::string_view>& names)
    : t_(&t), path_(std::move(path)), d_(&d) {
  for (auto&& [k, v] : t) {
    if (std::find(names.begin(), names.end(), k.str()) != names.end()) continue;
    std::string msg = "unknown key";
    const std::string hint = closest(k.str(), names);
    if (!hint.empty()) msg += "; did you mean '" + hint + "'?";
    else {
      msg += "; expected one of:";
      for (std::string_view n : names) msg += " " + std::string(n);
    }
    d.error(k.source(), key_path(k.str()), msg);
  }
}

std::string TableReader::key_path(std::string_view key) const {
  // A key is any TOML string: a long or binary one is shown quoted and cut.
  const bool plain = key.size() <= kQuoteChars && std::all_of(key.begin(), key.end(), [](char c) {
    return static_cast<unsigned char>(c) >= 0x20 && c != 0x7f;
  });
  const std::string k = plain ? std::string(key) : quote_token(key);
  return path_.empty() ? k : path_ + "." + k;
}

void TableReader::error(std::string_view key, std::string message) {
  const toml::node* n = t_->get(key);
  d_->error(n ? n->source() : t_->source(), key_path(key), std::move(message));
}

void TableReader::type_error(std::string_view key, const toml::node& n, std::string_view expected) {
  d_->error(n.source(), key_path(key), "expected " + std::string(expected) + ", found " + describe(n));
}

std::optional<double> TableReader::number(std::string_view key, const Range& r) {
  const toml::node* n = t_->get(key);
  return n ? read_number(*n, key_path(key), r, *d_) : std::nullopt;
}

std::optional<long long> TableReader::integer(std::string_view key, long long lo, long long hi) {
  const toml::node* n = t_->get(key);
  if (!n) return std::nullopt;
  const std::string what = "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  auto i = n->as_integer();
  if (!i) {
    type_error(key, *n, what);
    return std::nullopt;
  }
  if (i->get() < lo || i->get() > hi) {
    type_error(key, *n, what);
    return std::nullopt;
  }
  return i->get();
}

std::optional<bool> TableReader::boolean(std::string_view key) {
  const toml::node* n = t_->get(key);
  if (!n) return std::nullopt;
  if (auto b = n->as_boolean()) return b->get();
  type_error(key, *n, "true or false");
  return std::nullopt;
}

std::optional<std::string> TableReader::string(std::string_view key) {
  const toml::node* n = t_->get(key);
  if (!n) return std::nullopt;
  if (auto s = n->as_string()) return s->get();
  type_error(key, *n, "a string");
  return std::nullopt;
}

std::optional<Eigen::Vector3d> TableReader::vec3(std::string_view key, const Range& r) {
  const toml::node* n = t_->get(key);
  if (!n) return std::nullopt;
  const toml::array* a = n->as_array();
  if (!a || a->size() != 3) {
    type_error(key, *n, "an array of 3 numbers [x, y, z]");
    return std::nullopt;
  }
  Eigen::Vector3d v;
  bool ok = true;
  for (int k = 0; k < 3; ++k) {
    auto x = read_number(*a->get(static_cast<std::size_t>(k)), key_path(key) + "[" + std::to_string(k) + "]", r, *d_);
    if (x) v[k] = *x;
    else ok = false;
  }
  return ok ? std::optional<Eigen::Vector3d>(v) : std::nullopt;
}

std::optional<std::vector<std::string>> TableReader::strings(std::string_view key) {
  const toml::node* n = t_->get(key);
  if (!n) return std::nullopt;
  const toml::array* a = n->as_array();
  if (!a) {
    type_error(key, *n, "an array of strings");
    return std::nullopt;
  }
  std::vector<std::string> out;
  bool ok = true;
  for (std::size_t i = 0; i < a->size(); ++i) {
    if (auto s = a->get(i)->as_string()) out.push_back(s->get());
    else {
      d_->error(a->get(i)->source(), key_path(key) + "[" + std::to_string(i) + "]",
                "expected a string, found " + describe(*a->get(i)));
      ok = false;
    }
  }
  return ok ? std::optional(out) : std::nullopt;
}

const toml::table* TableReader::subtable(std::string_view key) {
  const toml::node* n = t_->get(key);
  if (!n) return nullptr;
  if (auto t = n->as_table()) return t;
  type_error(key, *n, "a table");
  return nullptr;
}

std::vector<const toml::table*> TableReader::tables(std::string_view key) {
  std::vector<const toml::table*> out;
  const toml::node* n = t_->get(key);
  if (!n) return out;
  const toml::array* a = n->as_array();
  if (!a) {
    type_error(key, *n, "an array of tables ([[" + key_path(key) + "]])");
    return out;
  }
  for (std::size_t i = 0; i < a->size(); ++i) {
    if (auto t = a->get(i)->as_table()) out.push_back(t);
    else
      d_->error(a->get(i)->source(), key_path(key) + "[" + std::to_string(i) + "]",
                "expected a table, found " + describe(*a->get(i)));
  }
  return out;
}

}  // namespace tumble::scene::detail
