// `tumble render`'s pipeline: a scene simulated, drawn frame by frame into an
// output folder (PNG files written atomically, a manifest, resume, shards)
// and encoded into a video, or streamed straight into ffmpeg.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "render/gl_context.hpp"
#include "run/listener.hpp"
#include "scene/scene.hpp"

namespace tumble::run {

struct RenderRequest {
  const scene::Scene& scene;  ///< its [output] FrameSettings already hold the command's options
  std::filesystem::path dir;  ///< the output folder (made when missing)
  std::string frames;         ///< "A:B" (a shard), empty for every frame
  bool resume = false, force = false;
  bool stream = false;        ///< frames piped into ffmpeg only, no PNG (--frames-out none)
  render::GlBackend backend = render::GlBackend::osmesa;
  std::string scene_arg;      ///< the scene as the user named it, for "run it again" hints
  std::optional<int> gpu = {};  ///< EGL device (--gpu, TUMBLE_EGL_DEVICE); nullopt: automatic
  int jobs = 0;               ///< frame encoder threads; 0: render::worker_threads()
  /// How the caller runs this again, given the command line's flags for it
  /// (" --resume", " --frames A:B --resume"); unset: `tumble render SCENE -o DIR` + flags.
  std::function<std::string(const std::string& flags)> rerun = {};
};

/// Renders `r`. Throws InputError (bad range, a folder holding another render
/// without `force`) or io::IoError (disk); else says how it ended.
Outcome render_scene(const RenderRequest& r, Listener& l);

}  // namespace tumble::run
