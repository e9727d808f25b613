// `tumble bench --render`: end-to-end frames per second of the demo at the
// default ("high": FXAA) and at 4x MSAA, the encode-only limit on the same
// frames, both video paths, and FXAA's pixels against 4x MSAA's, in one run.
#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace tumble::bench {

/// One scene's anti-aliasing measured against 4x MSAA (the reference), over
/// a few frames: mean RMS difference (0..255 levels) and the mean fraction of
/// pixels whose largest channel differs by more than 8 levels.
struct AaQuality {
  std::string scene;
  int frames = 0;
  double fxaa_rms = 0, fxaa_over = 0;  ///< FXAA ("high") against 4x MSAA
  double none_rms = 0, none_over = 0;  ///< no anti-aliasing against 4x MSAA
};

/// One way to the video: frames/s and CPU ms a frame, or why there is none
/// (ffmpeg missing, or its error).
struct VideoRow {
  double fps = 0, cpu_ms = 0;
  std::string error;
};

struct RenderBenchResult {
  long frames = 0;
  int threads = 0;              ///< frame encoder threads (--jobs, TUMBLE_JOBS, else the usable cores)
  std::string gl;               ///< GL vendor, renderer, version and display or device
  bool hardware_gpu = false;    ///< the renderer is a GPU, not llvmpipe and the like
  bool gl_fxaa = false;         ///< "high"'s FXAA ran as a GL pass
  std::string paths, other_paths;  ///< the GPU paths "high" used, and the others measured beside
  double other_paths_fps = 0, other_paths_cpu_ms = 0;  ///< end to end, FXAA, with the other paths
  std::string video_encoder;    ///< "libx264 ultrafast"
  std::string stream_threads;   ///< ", 1 thread(s)" when x264's threads are set (while frames are drawn)
  double end_to_end_fps = 0;  ///< "high" (FXAA): simulate + draw + read back + encode + write, frames/s
  double encode_only_fps = 0; ///< encode + write of the same frames, frames/s
  double render_ms = 0;       ///< mean build + draw + read-back time per frame ("high"), ms
  double cpu_ms = 0;          ///< CPU time (all threads, user + system) per frame end to end ("high"), ms
  double msaa_end_to_end_fps = 0, msaa_render_ms = 0, msaa_cpu_ms = 0;  ///< the same with 4x MSAA
  /// Frames to an H.264 video: through PNG files (end to end, then ffmpeg
  /// reads them), and piped raw (--frames-out none); CPU is tumble + ffmpeg.
  VideoRow png_video, stream_video;
  std::vector<AaQuality> quality;
  std::string markdown;       ///< what render.md holds
};

/// Renders the first `frames` frames of `scene_path` at 1280×720 into
/// `out_dir` with FXAA and with 4x MSAA, encodes the same images again, and
/// compares FXAA and no anti-aliasing with 4x MSAA on `scene_path` and
/// `quality_scenes`. Writes render.md there.
RenderBenchResult run_render_bench(const std::filesystem::path& scene_path, long frames,
                                   const std::filesystem::path& out_dir, std::ostream& log,
                                   const std::vector<std::filesystem::path>& quality_scenes = {}, int jobs = 0);

}  // namespace tumble::bench
