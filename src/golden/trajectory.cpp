#include "golden/trajectory.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <vector>

namespace tumble::golden {

namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) {
    if (!l.empty() && l.back() == '\r') l.pop_back();
    if (!l.empty()) out.push_back(l);
  }
  return out;
}

std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line);
  for (std::string f; std::getline(in, f, ',');) out.push_back(f);
  return out;
}

bool parse_number(const std::string& s, double& v) {
  if (s.empty()) return false;
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

}  // namespace

TrajectoryComparison compare_trajectories(const std::string& actual_csv, const std::string& expected_csv,
                                          const TrajectoryTolerance& tol) {
  TrajectoryComparison r;
  const auto a = lines_of(actual_csv), e = lines_of(expected_csv);
  auto fail = [&](const std::string& why) {
    r.pass = false;
    r.summary = why;
    return r;
  };
  if (e.empty() || e[0] != io::trajectory_header()) return fail("expected trajectory: missing or unknown header");
  if (a.empty() || a[0] != io::trajectory_header()) return fail("actual trajectory: missing or unknown header");
  if (a.size() != e.size())
    return fail("row count differs: actual " + std::to_string(a.size() - 1) + ", expected " +
                std::to_string(e.size() - 1) + " (a run diverged, or the times changed)");
  const auto names = fields_of(io::trajectory_header());
  std::string worst_text;
  char buf[400];
  for (std::size_t i = 1; i < a.size(); ++i) {
    const auto fa = fields_of(a[i]), fe = fields_of(e[i]);
    const std::string where = "row " + std::to_string(i);
    if (fa.size() != names.size() || fe.size() != names.size()) return fail(where + ": expected " + std::to_string(names.size()) + " columns");
    if (fa[1] != fe[1]) return fail(where + ": body '" + fa[1] + "', expected '" + fe[1] + "'");
    for (std::size_t c = 0; c < names.size(); ++c) {
      if (c == 1) continue;
      double va = 0, ve = 0;
      if (!parse_number(fa[c], va) || !parse_number(fe[c], ve))
        return fail(where + ": column " + names[c] + ": not a number ('" + fa[c] + "' vs '" + fe[c] + "')");
      const double bound = tol.atol + tol.rtol * std::abs(ve);
      const double ratio = std::isfinite(va) && std::isfinite(ve) ? std::abs(va - ve) / bound
                           : (va == ve ? 0.0 : INFINITY);
      if (c == 0 && ratio > 1e-3) return fail(where + ": t = " + fa[0] + ", expected t = " + fe[0]);
      if (ratio > r.worst || (r.worst == 0 && worst_text.empty())) {
        r.worst = ratio;
        std::snprintf(buf, sizeof buf, "worst: t = %s body %s column %s: actual %.17g, expected %.17g (|diff| %.3g, allowed %.3g)",
                      fe[0].c_str(), fe[1].c_str(), names[c].c_str(), va, ve, std::abs(va - ve), bound);
        worst_text = buf;
      }
    }
    ++r.rows;
  }
  r.pass = r.worst <= 1.0;
  std::snprintf(buf, sizeof buf, "%ld rows, tolerance |a-e| <= %g + %g |e|: %s; ", r.rows, tol.atol, tol.rtol,
                r.pass ? "within" : "PHYSICS CHANGED");
  r.summary = buf + worst_text;
  return r;
}

}  // namespace tumble::golden
