#include "golden/report.hpp"

#include <optional>
#include <sstream>
#include <stdexcept>

#include "base/error.hpp"
#include "base/input_file.hpp"
#include "io/atomic_file.hpp"
#include "io/png.hpp"

namespace tumble::golden {

namespace fs = std::filesystem;

std::string html_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      default: o += c;
    }
  }
  return o;
}

namespace {

constexpr std::string_view kTitleTag = "<title>tumble golden: ";  // every report's, old and new
constexpr std::size_t kMaxReportBytes = std::size_t(64) << 20;

/// The img/ files an earlier report's index.html shows (src="img/NAME").
std::vector<std::string> report_images(const std::string& html) {
  std::vector<std::string> out;
  constexpr std::string_view tag = "src=\"img/";
  for (std::size_t at = html.find(tag); at != std::string::npos; at = html.find(tag, at + 1)) {
    const std::size_t begin = at + tag.size(), end = html.find('"', begin);
    if (end == std::string::npos) break;
    const std::string name = html.substr(begin, end - begin);
    if (!name.empty() && name.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_.-") ==
                             std::string::npos && name != "." && name != "..")
      out.push_back(name);
  }
  return out;
}

}  // namespace

Report::Report(fs::path dir, std::string title) : dir_(std::move(dir)), title_(std::move(title)) {
  const fs::path index = dir_ / "index.html";
  const std::optional<std::string> old = read_file_if_exists(index, kMaxReportBytes, "golden report");
  if (!old) return;
  // Only what an earlier report wrote goes: its index.html and the images it shows.
  if (old->find(kTitleTag) == std::string::npos || old->find(kTitleTag) > 512)
    throw InputError("--report " + dir_.string() + ": " + index.string() +
                     " was not written by tumble golden; refusing to replace it (choose another --report folder)");
  std::error_code ec;
  for (const std::string& name : report_images(*old)) fs::remove(dir_ / "img" / name, ec);
  fs::remove(dir_ / "img", ec);  // only when empty now
  if (!fs::remove(index, ec) && ec) throw io::IoError("cannot remove " + index.string() + ": " + ec.message());
}

void Report::add_image(const std::string& id, const std::string& title, const io::Image& actual,
                       const io::Image* expected, const Comparison* cmp, const CompareOptions& options, bool pass,
                       const std::string& status, const std::string& note) {
  Case c;
  c.title = title;
  c.status = status;
  c.pass = pass;
  c.note = note;
  c.figures = cmp ? cmp->summary : "";
  if (!pass) {
    fs::create_directories(dir_ / "img");
    auto put = [&](const std::string& kind, const io::Image& img) {
      const std::string rel = "img/" + id + "." + kind + ".png";
      io::write_png_atomic(dir_ / rel, img);
      return rel;
    };
    // The offending region is outlined on actual, expected and difference
    // (same box on each); the mask shows the raw over-threshold pixels.
    const bool compared = expected && cmp && !cmp->size_mismatch;
    auto outlined = [&](io::Image img) {
      if (compared) outline_offenders(img, *cmp);
      return img;
    };
    c.actual = put("actual", outlined(actual));
    if (expected) c.expected = put("expected", outlined(*expected));
    if (compared) {
      c.diff = put("diff", outlined(amplified_difference(actual, *expected)));
      c.mask = put("mask", over_threshold_mask(actual, *expected, options.max_delta));
    }
  }
  cases_.push_back(std::move(c));
}

void Report::add_text(const std::string& title, bool pass, const std::string& status, const std::string& text) {
  Case c;
  c.title = title;
  c.pass = pass;
  c.status = status;
  c.figures = text;
  cases_.push_back(std::move(c));
}

bool Report::any_failure() const {
  for (const Case& c : cases_)
    if (!c.pass) return true;
  return false;
}

fs::path Report::write() const {
  fs::create_directories(dir_);
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" << html_escape(title_) << "</title>\n"
    << "<style>body{font-family:sans-serif;margin:1em;background:#fafafa}"
       "table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:4px 8px;vertical-align:top}"
       ".fail{color:#b00;font-weight:bold}.pass{color:#080}figure{display:inline-block;margin:4px}"
       "figcaption{text-align:center;font-size:90%}img{image-rendering:pixelated;border:1px solid #888}"
       ".case{background:#fff;border:1px solid #ddd;margin:1em 0;padding:0.5em}</style></head><body>\n"
    << "<h1>" << html_escape(title_) << "</h1>\n";
  int failed = 0;
  for (const Case& c : cases_) failed += !c.pass;
  h << "<p>" << failed << " of " << cases_.size() << " cases failed. Diff: |actual − expected| × 16; "
    << "mask: pixels over the threshold in magenta on the expected image darkened. "
    << "Outlined on actual, expected and difference: the largest connected region of differing pixels "
    << "(yellow) and, when over its limit, the window of the largest mean difference (cyan).</p>\n";
  for (const Case& c : cases_) {
    if (c.pass) continue;
    h << "<div class=\"case\"><h2><span class=\"fail\">" << html_escape(c.status) << "</span> " << html_escape(c.title)
      << "</h2>\n<p>" << html_escape(c.figures) << "</p>\n";
    if (!c.note.empty()) h << "<p><small>" << html_escape(c.note) << "</small></p>\n";
    const std::pair<const char*, const std::string*> figs[] = {
        {"actual", &c.actual}, {"expected", &c.expected}, {"difference ×16", &c.diff}, {"over threshold", &c.mask}};
    for (const auto& [caption, src] : figs)
      if (!src->empty())
        h << "<figure><a href=\"" << html_escape(*src) << "\"><img src=\"" << html_escape(*src)
          << "\"></a><figcaption>" << caption << "</figcaption></figure>\n";
    h << "</div>\n";
  }
  h << "<h2>All cases</h2>\n<table><tr><th>case</th><th>status</th><th>figures</th></tr>\n";
  for (const Case& c : cases_)
    h << "<tr><td>" << html_escape(c.title) << "</td><td class=\"" << (c.pass ? "pass" : "fail") << "\">"
      << html_escape(c.status) << "</td><td>" << html_escape(c.figures) << "</td></tr>\n";
  h << "</table>\n</body></html>\n";
  const fs::path path = dir_ / "index.html";
  io::atomic_write_file(path, h.str());
  return path;
}

}  // namespace tumble::golden
