// The failure report of a golden run: for every failing image the actual,
// the expected, an amplified difference and the over-threshold mask as PNGs
// under <dir>/img/, and one <dir>/index.html showing them side by side with
// the figures (failures first, then the passing cases as one table).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "golden/compare.hpp"
#include "io/image.hpp"

namespace tumble::golden {

class Report {
 public:
  /// Removes a previous report in `dir` (its index.html and the img/ files it
  /// shows), so a stale report never outlives a passing run; nothing else in
  /// `dir` is touched. An index.html that tumble did not write is refused
  /// (InputError) before any work. Creates nothing until write().
  Report(std::filesystem::path dir, std::string title);

  /// One image case. `expected` may be null (missing or unreadable golden);
  /// `cmp` is null then too. Failing cases write their images at once.
  /// `note` is free text shown under the figures (e.g. the GL renderers).
  void add_image(const std::string& id, const std::string& title, const io::Image& actual,
                 const io::Image* expected, const Comparison* cmp, const CompareOptions& options, bool pass,
                 const std::string& status, const std::string& note);

  /// A case without images (golden physics).
  void add_text(const std::string& title, bool pass, const std::string& status, const std::string& text);

  bool any_failure() const;
  /// Writes index.html (plus img/ written so far). Returns its path.
  std::filesystem::path write() const;
  const std::filesystem::path& dir() const { return dir_; }

 private:
  struct Case {
    std::string title, status, figures, note, actual, expected, diff, mask;
    bool pass = false;
  };
  std::filesystem::path dir_;
  std::string title_;
  std::vector<Case> cases_;
};

/// Minimal HTML escaping (&, <, >, ").
std::string html_escape(const std::string& s);

}  // namespace tumble::golden
