// Renders chosen frames of a scene into memory (no files): what `tumble
// golden` compares, and the same pixels `tumble render --frames k:k` writes.
#pragma once

#include <string>
#include <vector>

#include "compose/frame_builder.hpp"
#include "run/frame_range.hpp"
#include "render/gl_context.hpp"
#include "io/image.hpp"
#include "scene/scene.hpp"

namespace tumble::run {

/// A scene simulated at its frame times t_k = k/fps up to a last frame.
class SceneFrames {
 public:
  /// Simulates up to frame `last_needed`, or over the whole run when the
  /// camera is automatic (it frames every body over the whole run, so a
  /// shorter simulation would move the camera).
  SceneFrames(const scene::Scene& s, long last_needed);

  double fps() const { return fps_; }
  long count() const { return count_; }  ///< frames of the whole scene
  const std::vector<scene::Run>& runs() const { return runs_; }

  /// Draws frames `ks` at the size and anti-aliasing of `f` on `ctx`.
  /// Throws InputError for a frame that was not simulated or diverged before it.
  std::vector<io::Image> render(render::GlContext& ctx, const std::vector<long>& ks, const scene::FrameSettings& f,
                                int* samples_used = nullptr) const;

  /// The trajectory at frames `ks` in the columns of `tumble simulate`; in a
  /// [compare] scene the body column is "<method>:<body>".
  std::string trajectory_csv(const std::vector<long>& ks) const;

 private:
  const scene::Scene& scene_;
  double fps_;
  long count_;
  std::vector<scene::Run> runs_;
};

}  // namespace tumble::run
