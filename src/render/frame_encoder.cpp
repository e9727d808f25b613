#include "render/frame_encoder.hpp"

#include <algorithm>

#include "io/png.hpp"

namespace tumble::render {

FrameEncoder::FrameEncoder(int threads, std::size_t capacity)
    : capacity_(std::max<std::size_t>(capacity, 1)),
      max_spare_(capacity_ + static_cast<std::size_t>(std::max(threads, 1))) {
  const int n = std::max(threads, 1);
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
  std::unique_lock lock(mutex_);
  rethrow_locked(lock);
  space_or_idle_.wait(lock, [&] { return queue_.size() < capacity_ || error_; });
  rethrow_locked(lock);
  queue_.emplace_back(std::move(path), std::move(image));
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

void FrameEncoder::worker() {
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
    try {
      io::write_png_atomic(job.first, job.second);
    } catch (...) {
      failure = std::current_exception();
    }

    lock.lock();
    --in_flight_;
    if (failure) {
      if (!error_) error_ = failure;
    } else {
      ++written_;
    }
    // Bounded: at most one spare per frame that can be in the pipeline.
    if (spare_.size() < max_spare_) spare_.push_back(std::move(job.second));
    space_or_idle_.notify_all();
  }
}

}  // namespace tumble::render
