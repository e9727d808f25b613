// Renders chosen frames of a scene into memory (no files): what `tumble
// golden` compares, and the same pixels `tumble render --frames k:k` writes.
#pragma once

#include <string>
#include <vector>

#include "app/render_job.hpp"
#include "render/gl_context.hpp"
#include "io/image.hpp"
#include "scene/scene.hpp"

namespace tumble::app {

/// One anti-aliasing choice, as the renderer takes it: the scene's
/// [output] aa and msaa, or a case of `tumble golden --aa`.
struct AaSetting {
  scene::Antialias mode = scene::Antialias::fxaa;
  int msaa = 4;  ///< samples, used with mode msaa
  int samples() const { return mode == scene::Antialias::msaa ? msaa : 0; }
  bool fxaa() const { return mode == scene::Antialias::fxaa; }
  /// "fxaa", "msaa2", "msaa4", or "msaa0" for none (the golden files' names).
  std::string name() const;
};
AaSetting aa_setting(const scene::OutputConfig& out);
/// Parses a name of AaSetting::name() (also "none" for msaa0); throws
/// InputError naming `option` for anything else.
AaSetting parse_aa_setting(const std::string& text, const std::string& option);

/// The GL backend of `--gl` (or, when empty, of env TUMBLE_GL): an InputError
/// naming the option for an unknown name, so it fails before any work.
render::GlBackend parse_backend_option(const std::string& gl);

/// A scene simulated at its frame times t_k = k/fps up to a last frame.
class SceneFrames {
 public:
  /// Simulates up to frame `last_needed`, or over the whole run when the
  /// camera is automatic (it frames every body over the whole run, so a
  /// shorter simulation would move the camera).
  SceneFrames(const scene::Scene& s, long last_needed);

  double fps() const { return fps_; }
  long count() const { return count_; }  ///< frames of the whole scene
  const std::vector<Run>& runs() const { return runs_; }

  /// Draws frames `ks` at width × height anti-aliased by `aa` on `ctx`.
  /// Throws InputError for a frame that was not simulated or diverged before it.
  std::vector<io::Image> render(render::GlContext& ctx, const std::vector<long>& ks, int width, int height,
                                AaSetting aa, int* samples_used = nullptr) const;

  /// The trajectory at frames `ks` in the columns of `tumble simulate`; in a
  /// [compare] scene the body column is "<method>:<body>".
  std::string trajectory_csv(const std::vector<long>& ks) const;

 private:
  const scene::Scene& scene_;
  double fps_;
  long count_;
  std::vector<Run> runs_;
};

}  // namespace tumble::app
