// Typed, located access to TOML tables: every getter validates type and range
// and records a Diagnostic (never throws), so one load reports every problem.
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>
#include <toml++/toml.h>

#include "base/format.hpp"
#include "scene/scene.hpp"

namespace tumble::scene::detail {

/// Collects diagnostics of one load; caps them so a huge broken array stays readable.
class Diagnostics {
 public:
  /// `options`: scene keys set on the command line, with the option that set
  /// each; errors at those keys name the option instead of a file position.
  /// `located` false: the document was built in code (no lines), so messages
  /// say "file: error: ..." without a position.
  explicit Diagnostics(std::string file, std::vector<std::pair<std::string, std::string>> options = {},
                       bool located = true)
      : file_(std::move(file)), options_(std::move(options)), located_(located) {}
  void error(const toml::source_region& at, std::string key, std::string message);
  void warning(const toml::source_region& at, std::string key, std::string message);
  bool ok() const { return errors_.empty(); }
  std::size_t error_count() const { return errors_.size(); }
  /// Errors in file order (the "too many errors" marker stays last).
  std::vector<Diagnostic> take_errors();
  std::vector<std::string> take_warnings() { return std::move(warnings_); }
  const std::string& file() const { return file_; }
  /// "file:line:col: error: key: message", for errors thrown at once (not collected).
  std::string located(const toml::source_region& at, std::string key, std::string message) const {
    return make(at, std::move(key), std::move(message)).str();
  }

 private:
  Diagnostic make(const toml::source_region& at, std::string key, std::string message) const;
  std::string file_;
  std::vector<std::pair<std::string, std::string>> options_;
  bool located_ = true;
  std::vector<Diagnostic> errors_;
  std::vector<std::string> warnings_;
};

/// Allowed interval of a number; `what` is how the expectation reads in messages.
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  std::string what = "a finite number";
  static Range any() { return {}; }
  static Range positive() { return {0, std::numeric_limits<double>::infinity(), true, "a finite number > 0"}; }
  static Range non_negative() { return {0, std::numeric_limits<double>::infinity(), false, "a finite number >= 0"}; }
  static Range closed(double lo, double hi);
  bool contains(double v) const;
};

/// Short description of a value for "found ..." (type and value).
std::string describe(const toml::node& n);
/// Levenshtein distance (for did-you-mean).
std::size_t edit_distance(std::string_view a, std::string_view b);
/// Closest candidate within a small distance, or "".
std::string closest(std::string_view word, const std::vector<std::string_view>& candidates);

/// Reads one table. Reports unknown keys (with did-you-mean) on construction.
class TableReader {
 public:
  TableReader(const toml::table& t, std::string path, Diagnostics& d,
              const std::vector<std::string_view>& allowed);

  const toml::table& table() const { return *t_; }
  const std::string& path() const { return path_; }
  std::string key_path(std::string_view key) const;
  bool has(std::string_view key) const { return t_->contains(key); }
  const toml::node* node(std::string_view key) const { return t_->get(key); }
  /// Where to point when a key is missing: the table itself.
  const toml::source_region& where() const { return t_->source(); }

  std::optional<double> number(std::string_view key, const Range& r = Range::any());
  std::optional<long long> integer(std::string_view key, long long lo, long long hi);
  std::optional<bool> boolean(std::string_view key);
  std::optional<std::string> string(std::string_view key);
  /// Array of exactly 3 numbers, each within `r`.
  std::optional<Eigen::Vector3d> vec3(std::string_view key, const Range& r = Range::any());
  std::optional<std::vector<std::string>> strings(std::string_view key);
  const toml::table* subtable(std::string_view key);
  /// An array of tables ([[key]]); a single inline table is rejected with a hint.
  std::vector<const toml::table*> tables(std::string_view key);

  void error(std::string_view key, std::string message);  // at the key's value, else the table
  Diagnostics& diag() { return *d_; }

 private:
  void type_error(std::string_view key, const toml::node& n, std::string_view expected);
  const toml::table* t_;
  std::string path_;
  Diagnostics* d_;
};

/// Reads a node as a finite number (integer or float), reporting errors under `key`.
std::optional<double> read_number(const toml::node& n, const std::string& key, const Range& r, Diagnostics& d);

}  // namespace tumble::scene::detail
