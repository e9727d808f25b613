// `tumble render --frames-out none`: every frame drawn and piped straight into
// ffmpeg (raw RGB), no PNG written. All or nothing: an interrupted stream
// leaves no video and nothing to resume.
#pragma once

#include <filesystem>
#include <string>

#include "app/render_job.hpp"
#include "app/render_output.hpp"
#include "app/video.hpp"
#include "render/renderer.hpp"

namespace tumble::app {

struct StreamJob {
  const std::filesystem::path& dir;
  const scene::Scene& scene;
  const FrameBuilder& builder;
  render::Renderer& renderer;
  Manifest& manifest;         ///< filled in; written at every outcome
  const Existing& existing;   ///< a replaced render's frames go once the video exists
  long good;                  ///< frames the simulation reached (count, unless it diverged)
  bool progress;
  StopPoll stop;
  std::string rerun;          ///< the command that runs it again, for messages
  std::string diverged;       ///< why the simulation stopped early (when good < count)
};

/// Draws frames 0..count-1 into the video. Returns the exit code: 0, 1 (ffmpeg
/// missing or failed), 3 (diverged: the video holds the frames before), 130/143.
int stream_render(const StreamJob& job);

}  // namespace tumble::app
