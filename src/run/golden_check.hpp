// `tumble golden`'s checks: the golden trajectory and golden images of a
// scene compared with this build's (or written, with --update), each case a
// line on `out` and, when it fails, a section of the HTML report.
#pragma once

#include <filesystem>
#include <ostream>
#include <vector>

#include "golden/compare.hpp"
#include "golden/report.hpp"
#include "golden/trajectory.hpp"
#include "render/gl_context.hpp"
#include "run/frame_renderer.hpp"
#include "scene/frame_settings.hpp"

namespace tumble::run {

struct GoldenCheck {
  const scene::Scene& s;
  const SceneFrames& frames;
  const std::vector<long>& ks;  ///< golden frames, sorted
  std::filesystem::path dir;    ///< the goldens' folder
  golden::Report& report;
  std::ostream& out;
  bool update = false;          ///< write the goldens instead of checking them
  long every = 10;              ///< trajectory rows: every N-th frame
  golden::CompareOptions cmp;
  golden::TrajectoryTolerance tol;
  int failed = 0, cases = 0, written = 0;

  /// The golden trajectory: every `every`-th frame up to the last golden frame, plus those.
  void check_physics();
  /// Every golden frame in anti-aliasing case `f` (its size too).
  void check_images(const scene::FrameSettings& f, render::GlContext& ctx, render::GlBackend backend);
  void line(bool pass, const std::string& status, const std::string& what, const std::string& figures);
  std::string missing(const std::filesystem::path& path) const;
};

}  // namespace tumble::run
