// `tumble bench --render`: end-to-end frames per second of the demo, and the
// encode-only limit on the same frames, measured in one run.
#pragma once

#include <filesystem>
#include <ostream>

namespace tumble::app {

struct RenderBenchResult {
  long frames = 0;
  double end_to_end_fps = 0;  ///< simulate + draw + read back + encode + write, frames/s
  double encode_only_fps = 0; ///< encode + write of the same frames, frames/s
  double render_ms = 0;       ///< mean draw + read-back time per frame, ms
  /// Frames to an H.264 video, frames/s (0 without ffmpeg): through PNG files
  /// (end to end, then ffmpeg reads them), and piped raw (--frames-out none).
  double png_video_fps = 0, stream_video_fps = 0;
  /// The same two paths in CPU time (tumble + ffmpeg, user + system), ms per frame.
  double png_video_cpu_ms = 0, stream_video_cpu_ms = 0;
};

/// Renders the first `frames` frames of `scene_path` at 1280×720 with 4× MSAA
/// into `out_dir`, then encodes the same images again. Writes render.md there.
RenderBenchResult run_render_bench(const std::filesystem::path& scene_path, long frames,
                                   const std::filesystem::path& out_dir, std::ostream& log);

}  // namespace tumble::app
