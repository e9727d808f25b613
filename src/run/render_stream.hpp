// `tumble render --frames-out none`: every frame drawn and piped straight into
// ffmpeg (raw RGB), no PNG written. All or nothing: an interrupted stream
// leaves no video and nothing to resume.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include "render/renderer.hpp"
#include "run/listener.hpp"
#include "compose/frame_builder.hpp"
#include "run/frame_range.hpp"
#include "run/render_output.hpp"
#include "run/video.hpp"
#include "run/video_stream.hpp"

namespace tumble::run {

struct StreamJob {
  const std::filesystem::path& dir;
  const scene::Scene& scene;
  const compose::FrameBuilder& builder;
  render::Renderer& renderer;
  Manifest& manifest;         ///< filled in; written at every outcome
  const Existing& existing;   ///< a replaced render's frames go once the video exists
  long good;                  ///< frames the simulation reached (count, unless it diverged)
  Listener& listener;         ///< notes, progress, stop requests
  std::string rerun;          ///< the command that runs it again, for messages
  std::string diverged;       ///< why the simulation stopped early (when good < count)
  VideoEncoder encoder;       ///< the H.264 encoder (choose_video_encoder)
  int jobs = 0;               ///< worker threads finishing frames (render::worker_threads)
};

/// How far stream_frames got: frames handed to the stream, and the stop
/// signal that ended it early (0 = none).
struct Streamed {
  long frames = 0;
  int signal = 0;
};

/// Draws frames 0..count-1 into `stream` until `stop` answers or ffmpeg stops
/// reading. The drawing thread only draws and reads back; `jobs` workers
/// (render::FrameEncoder) finish the frames (FXAA) meanwhile, and the stream
/// takes them strictly in order. `advance` is told each frame drawn, `notes`
/// (when given) each frame's layout notes.
Streamed stream_frames(render::Renderer& renderer, const compose::FrameBuilder& builder, long count, VideoStream& stream,
                       int jobs, const StopPoll& stop, const std::function<void(long)>& advance = {},
                       compose::LayoutNotes* notes = nullptr);

/// Draws frames 0..count-1 into the video: done, failed (ffmpeg missing or
/// failed), diverged (the video holds the frames before) or interrupted.
Outcome stream_render(const StreamJob& job);

}  // namespace tumble::run
