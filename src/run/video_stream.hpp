// A video made from frames in memory: raw RGB rows piped into ffmpeg's stdin
// (-f rawvideo), no PNG written or read (`tumble render --frames-out none`).
#pragma once

#include <sys/types.h>

#include <atomic>
#include <csignal>
#include <filesystem>

#include "run/video.hpp"
#include "io/image.hpp"

namespace tumble::run {

/// One ffmpeg process fed frame by frame. Its output goes to a temp name and
/// is renamed by finish(); abort(), a failure or the destructor kill ffmpeg
/// and remove the temp file, so the video is whole or absent.
class VideoStream {
 public:
  /// Starts ffmpeg for width × height rgb24 frames at `fps` (frames/s). Check
  /// status() before writing: missing_ffmpeg or failed when it could not start.
  VideoStream(int width, int height, int fps, VideoFormat format, int crf, std::filesystem::path output,
              const VideoEncoder& encoder = default_video_encoder());
  ~VideoStream();
  VideoStream(const VideoStream&) = delete;
  VideoStream& operator=(const VideoStream&) = delete;

  /// Writes one frame. A signal seen by `stop` while the pipe is full (ffmpeg
  /// busy; polled every 100 ms, so any thread may have caught it) ends the
  /// write: returns that signal, else 0. Throws nothing: a broken pipe
  /// (ffmpeg died) shows in finish(). One writer at a time, any thread.
  int write(const io::Image& frame, const StopPoll& stop);

  /// Ends the input, waits for ffmpeg and renames the video into place. A
  /// signal seen by `stop` meanwhile aborts (the result says interrupted).
  VideoResult finish(const StopPoll& stop = {});
  /// Kills ffmpeg, removes the temp file; the result says `interrupted` by `signal`.
  VideoResult abort(int signal);

  bool running() const { return pid_ > 0; }
  /// ffmpeg stopped reading (it exited): no use drawing more frames.
  bool broken() const { return broken_.load(); }
  const VideoResult& status() const { return status_; }

 private:
  // Exit code, or -1 - signal; with `stop`, polls it and returns early with
  // *stopped set (ffmpeg still running) when it answers.
  int wait_child(const StopPoll& stop = {}, int* stopped = nullptr);
  std::filesystem::path output_, tmp_;
  pid_t pid_ = -1;
  int in_ = -1;      // the write end of ffmpeg's stdin
  std::atomic<bool> broken_ = false;  // read by the drawing thread while a worker writes
  long frames_ = 0;  // written whole, for the check of the video
  int fps_ = 0;
  VideoFormat format_ = VideoFormat::mp4;
  struct sigaction old_pipe_ {};
  VideoResult status_;
};

}  // namespace tumble::run
