// Encodes and writes PNG frames on worker threads while the caller renders
// the next frame, or hands them, finished, to an ordered sink (ffmpeg's pipe).
// The queue is bounded, so a slow disk or encoder applies back-pressure
// instead of piling up frames in memory.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <filesystem>
#include <functional>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

#include "io/image.hpp"
#include "render/fxaa.hpp"

namespace tumble::render {

class FrameEncoder {
 public:
  /// Called on a worker with each frame's path once it is renamed into place
  /// (e.g. to record its checksum); what it throws is that frame's error.
  using OnWritten = std::function<void(const std::filesystem::path&)>;

  /// Instead of PNG files: each finished frame handed to `write` on a
  /// worker, in the order submitted and one at a time (e.g. into ffmpeg's
  /// pipe), while the other workers finish the next frames. What it throws
  /// is that frame's error.
  struct OrderedSink {
    std::function<void(const io::Image&)> write;
  };

  /// `threads` workers, 0 = render::worker_threads() (--jobs, TUMBLE_JOBS,
  /// else the cores this process may use); `capacity` queued frames, 0 = two
  /// per worker, so each has the next frame waiting while the GL thread draws.
  explicit FrameEncoder(int threads = 0, std::size_t capacity = 0, OnWritten on_written = {});
  /// The same workers and queue feeding `sink` (submit(RawFrame); a path is ignored).
  FrameEncoder(int threads, std::size_t capacity, OrderedSink sink);
  int threads() const { return static_cast<int>(workers_.size()); }
  std::size_t capacity() const { return capacity_; }
  /// Drains the queue and joins; errors not yet reported are dropped (call
  /// flush() first to see them).
  ~FrameEncoder();
  FrameEncoder(const FrameEncoder&) = delete;
  FrameEncoder& operator=(const FrameEncoder&) = delete;

  /// Queues a frame for write_png_atomic, blocking while the queue is full.
  /// Rethrows the first error of an earlier frame, if any.
  void submit(std::filesystem::path path, io::Image image);

  /// Same for a frame as read back: a worker finishes it (FXAA, or the plain
  /// conversion) before the encode, so that runs while the caller draws on.
  void submit(std::filesystem::path path, RawFrame frame);
  /// A frame for the ordered sink.
  void submit(RawFrame frame) { submit({}, std::move(frame)); }

  /// Waits until every submitted frame is on disk (or through the sink);
  /// rethrows the first error.
  void flush();

  std::size_t frames_written() const;

  /// The pixel storage of an already written frame (or an empty Image), to
  /// render the next frame into: fresh multi-MB buffers are page-faulted in
  /// on every frame otherwise, which costs as much as the PNG encode.
  io::Image recycle();
  /// The same for read-back buffers (submit(path, RawFrame)).
  RawFrame recycle_raw();

 private:
  struct Job {
    std::filesystem::path path;
    io::Image image;  // what is written, unless `raw` holds the frame
    RawFrame raw;     // rgba non-empty: finish it first
    std::size_t seq = 0;  // submission order: the sink's turn
  };
  void start(int threads, std::size_t capacity);
  void worker();
  void to_sink(std::size_t seq, const io::Image* image, std::exception_ptr& failure);
  void rethrow_locked(std::unique_lock<std::mutex>& lock);
  void push(Job job);

  mutable std::mutex mutex_;
  std::condition_variable work_ready_, space_or_idle_, turn_;
  std::deque<Job> queue_;
  std::vector<io::Image> spare_;  // written frames, kept for recycle()
  std::vector<RawFrame> spare_raw_;
  std::size_t capacity_;
  std::size_t max_spare_;  // fixed before the workers start (they read it)
  std::size_t in_flight_ = 0;
  std::size_t written_ = 0;
  std::size_t submitted_ = 0, next_out_ = 0;  // the sink takes frame next_out_ next
  bool stopping_ = false;
  std::exception_ptr error_;
  OnWritten on_written_;
  OrderedSink sink_;
  std::vector<std::thread> workers_;
};

}  // namespace tumble::render
