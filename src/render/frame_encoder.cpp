#include "render/frame_encoder.hpp"

#include <algorithm>

#include "io/png.hpp"
#include "render/worker_threads.hpp"

namespace tumble::render {

FrameEncoder::FrameEncoder(int threads, std::size_t capacity, OnWritten on_written)
    : on_written_(std::move(on_written)) {
  start(threads, capacity);
}

FrameEncoder::FrameEncoder(int threads, std::size_t capacity, OrderedSink sink) : sink_(std::move(sink)) {
  start(threads, capacity);
}

void FrameEncoder::start(int threads, std::size_t capacity) {
  const int n = threads > 0 ? threads : worker_threads();
  capacity_ = capacity > 0 ? capacity : 2 * static_cast<std::size_t>(n);
  max_spare_ = capacity_ + static_cast<std::size_t>(n);
  workers_.reserve(n);
  for (int i = 0; i < n; ++i) workers_.emplace_back([this] { worker(); });
}

FrameEncoder::~FrameEncoder() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  work_ready_.notify_all();
  for (std::thread& t : workers_) t.join();
}

void FrameEncoder::rethrow_locked(std::unique_lock<std::mutex>& lock) {
  if (!error_) return;
  // Report once; later frames are still attempted so a transient error does
  // not silently stop output.
  std::exception_ptr e = std::exchange(error_, nullptr);
  lock.unlock();
  std::rethrow_exception(e);
}

void FrameEncoder::submit(std::filesystem::path path, io::Image image) {
  push({std::move(path), std::move(image), {}});
}

void FrameEncoder::submit(std::filesystem::path path, RawFrame frame) {
  push({std::move(path), {}, std::move(frame)});
}

void FrameEncoder::push(Job job) {
  std::unique_lock lock(mutex_);
  rethrow_locked(lock);
  space_or_idle_.wait(lock, [&] { return queue_.size() < capacity_ || error_; });
  rethrow_locked(lock);
  job.seq = submitted_++;
  queue_.push_back(std::move(job));
  lock.unlock();
  work_ready_.notify_one();
}

void FrameEncoder::flush() {
  std::unique_lock lock(mutex_);
  space_or_idle_.wait(lock, [&] { return queue_.empty() && in_flight_ == 0; });
  rethrow_locked(lock);
}

std::size_t FrameEncoder::frames_written() const {
  const std::lock_guard lock(mutex_);
  return written_;
}

io::Image FrameEncoder::recycle() {
  const std::lock_guard lock(mutex_);
  if (spare_.empty()) return {};
  io::Image img = std::move(spare_.back());
  spare_.pop_back();
  return img;
}

RawFrame FrameEncoder::recycle_raw() {
  const std::lock_guard lock(mutex_);
  if (spare_raw_.empty()) return {};
  RawFrame raw = std::move(spare_raw_.back());
  spare_raw_.pop_back();
  return raw;
}

// Frames finish out of order on several workers; the sink takes them in
// order, one at a time. The frame before is in flight (the queue is FIFO), so
// the turn comes. A frame that failed (image null) passes its turn on.
void FrameEncoder::to_sink(std::size_t seq, const io::Image* image, std::exception_ptr& failure) {
  std::unique_lock lock(mutex_);
  turn_.wait(lock, [&] { return next_out_ == seq; });
  lock.unlock();
  if (image) try {
      sink_.write(*image);
    } catch (...) {
      failure = std::current_exception();
    }
  lock.lock();
  ++next_out_;
  lock.unlock();
  turn_.notify_all();
}

void FrameEncoder::worker() {
  Fxaa fxaa;           // this worker's scratch
  io::Image finished;  // a raw frame's image, reused
  std::unique_lock lock(mutex_);
  for (;;) {
    work_ready_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
    if (queue_.empty()) return;  // stopping and drained
    Job job = std::move(queue_.front());
    queue_.pop_front();
    ++in_flight_;
    lock.unlock();
    space_or_idle_.notify_all();  // a slot is free

    std::exception_ptr failure;
    const bool raw = !job.raw.rgba.empty();
    const io::Image& image = raw ? finished : job.image;
    try {
      // One thread each: the other workers and the drawing use the other cores.
      if (raw) finish_frame(job.raw, finished, fxaa, 1);
      if (!sink_.write) {
        io::write_png_atomic(job.path, image);
        if (on_written_) on_written_(job.path);
      }
    } catch (...) {
      failure = std::current_exception();
    }
    if (sink_.write) to_sink(job.seq, failure ? nullptr : &image, failure);

    lock.lock();
    --in_flight_;
    if (failure) {
      if (!error_) error_ = failure;
    } else {
      ++written_;
    }
    // Bounded: at most one spare per frame that can be in the pipeline.
    if (raw && spare_raw_.size() < max_spare_) spare_raw_.push_back(std::move(job.raw));
    if (!raw && spare_.size() < max_spare_) spare_.push_back(std::move(job.image));
    space_or_idle_.notify_all();
  }
}

}  // namespace tumble::render
