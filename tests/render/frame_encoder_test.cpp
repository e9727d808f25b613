#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <thread>
#include <vector>
#include <filesystem>
#include <string>

#include "render/frame_encoder.hpp"
#include "render/worker_threads.hpp"
#include "io/png.hpp"

namespace tumble::render {
namespace {
using io::Image;
using io::read_png;
namespace fs = std::filesystem;

Image solid(int w, int h, std::uint8_t v) {
  return Image{w, h, std::vector<std::uint8_t>(std::size_t(w) * h * 3, v)};
}

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(testing::TempDir()) / ("tumble_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(FrameEncoder, WritesEveryFrameInOrderOfContent) {
  const fs::path dir = fresh_dir("encoder_ok");
  {
    FrameEncoder enc(2, 2);
    for (int i = 0; i < 12; ++i) {
      enc.submit(dir / ("f" + std::to_string(i) + ".png"), solid(32, 16, std::uint8_t(i * 10)));
    }
    enc.flush();
    EXPECT_EQ(enc.frames_written(), 12u);
  }
  for (int i = 0; i < 12; ++i) {
    const Image img = read_png(dir / ("f" + std::to_string(i) + ".png"));
    ASSERT_EQ(img.width, 32);
    EXPECT_EQ(img.rgb[0], i * 10);
  }
  fs::remove_all(dir);
}

TEST(FrameEncoder, ThreadsAndQueueFollowTheJobs) {
  const FrameEncoder three(3);
  EXPECT_EQ(three.threads(), 3);
  EXPECT_EQ(three.capacity(), 6u);  // two frames a worker
  EXPECT_EQ(FrameEncoder(2, 5).capacity(), 5u);
  ::setenv("TUMBLE_JOBS", "4", 1);
  const FrameEncoder from_env;
  ::unsetenv("TUMBLE_JOBS");
  EXPECT_EQ(from_env.threads(), 4);
  EXPECT_EQ(from_env.capacity(), 8u);
  EXPECT_EQ(FrameEncoder().threads(), worker_threads());
}

TEST(FrameEncoder, PropagatesWriteErrors) {
  const fs::path dir = fresh_dir("encoder_fail");
  FrameEncoder enc(2, 2);
  enc.submit(dir / "nope" / "f.png", solid(8, 8, 1));
  EXPECT_THROW(enc.flush(), std::runtime_error);
  // The error is reported once; the encoder keeps working afterwards.
  enc.submit(dir / "ok.png", solid(8, 8, 1));
  EXPECT_NO_THROW(enc.flush());
  EXPECT_TRUE(fs::exists(dir / "ok.png"));
  fs::remove_all(dir);
}

TEST(FrameEncoder, RecyclesWrittenFrameStorage) {
  const fs::path dir = fresh_dir("encoder_recycle");
  FrameEncoder enc(1, 2);
  EXPECT_TRUE(enc.recycle().rgb.empty());  // nothing written yet
  enc.submit(dir / "a.png", solid(16, 16, 3));
  enc.flush();
  const Image spare = enc.recycle();
  EXPECT_GE(spare.rgb.capacity(), 16u * 16u * 3u);
  EXPECT_TRUE(enc.recycle().rgb.empty());  // handed out only once
  fs::remove_all(dir);
}

TEST(FrameEncoder, DestructorDrainsQueue) {
  const fs::path dir = fresh_dir("encoder_drain");
  {
    FrameEncoder enc(1, 8);
    for (int i = 0; i < 5; ++i) enc.submit(dir / (std::to_string(i) + ".png"), solid(64, 64, 7));
  }
  for (int i = 0; i < 5; ++i) EXPECT_TRUE(fs::exists(dir / (std::to_string(i) + ".png")));
  fs::remove_all(dir);
}

// A raw (read-back) frame is finished on a worker: the file holds what
// finish_frame makes on the caller's thread, with FXAA and without, for
// every frame whatever the number of workers.
TEST(FrameEncoder, RawFramesAreFinishedLikeOnTheCallersThread) {
  const fs::path dir = fresh_dir("encoder_raw");
  auto raw = [](int i, bool fxaa) {
    RawFrame f{std::vector<std::uint8_t>(std::size_t(48) * 32 * 4), 48, 32, fxaa};
    for (int y = 0; y < 32; ++y)  // a slanted edge, so FXAA has work; bottom row first
      for (int x = 0; x < 48; ++x)
        for (int c = 0; c < 4; ++c) f.rgba[(std::size_t(y) * 48 + x) * 4 + c] = c == 3 ? 255 : 3 * y > x + i ? 20 : 230;
    return f;
  };
  for (int threads : {1, 2}) {
    {
      FrameEncoder enc(threads, 2);
      for (int i = 0; i < 6; ++i) enc.submit(dir / (std::to_string(i) + ".png"), raw(i, i % 2 == 0));
      enc.flush();
    }
    for (int i = 0; i < 6; ++i) {
      Fxaa fxaa;
      Image want;
      finish_frame(raw(i, i % 2 == 0), want, fxaa);
      const Image got = read_png(dir / (std::to_string(i) + ".png"), ReadRole::own_output);  // written again next round
      EXPECT_TRUE(got.rgb == want.rgb) << "frame " << i << ", " << threads << " thread(s)";
      EXPECT_EQ(got.pixel(0, 0)[0], 20) << "top row: y = 31 is dark at x = 0";
    }
  }
  Image plain, anti;
  Fxaa fxaa;
  finish_frame(raw(0, false), plain, fxaa);
  finish_frame(raw(0, true), anti, fxaa);
  EXPECT_FALSE(plain.rgb == anti.rgb) << "FXAA did nothing to the edge";
  fs::remove_all(dir);
}

// The video path: frames finish on several workers in any order, the sink
// takes them in the order submitted and one at a time. Large frames before
// small ones finish last, so a sink fed as frames finish sees them out of order.
TEST(FrameEncoder, OrderedSinkTakesFramesInOrderOneAtATime) {
  auto raw = [](int i) {
    const int side = i % 3 == 0 ? 768 : 8;  // slow, then two fast
    return RawFrame{std::vector<std::uint8_t>(std::size_t(side) * side * 4, std::uint8_t(i)), side, side, true};
  };
  for (int threads : {1, 4}) {
    std::vector<int> seen;
    std::atomic<int> inside = 0, most = 0;
    {
      FrameEncoder enc(threads, 0, FrameEncoder::OrderedSink{[&](const Image& img) {
                         most = std::max(most.load(), ++inside);
                         std::this_thread::sleep_for(std::chrono::microseconds(200));
                         seen.push_back(img.rgb[0]);
                         if (img.rgb[0] == 4) {
                           --inside;
                           throw std::runtime_error("pipe closed at frame 4");
                         }
                         --inside;
                       }});
      int errors = 0;  // frame 4's, reported once by a later submit or the flush
      for (int i = 0; i < 30; ++i) try {
          enc.submit(raw(i));
        } catch (const std::runtime_error&) {  // this frame was not taken: again
          ++errors;
          enc.submit(raw(i));
        }
      try {
        enc.flush();
      } catch (const std::runtime_error&) {
        ++errors;
      }
      EXPECT_EQ(errors, 1);
      EXPECT_EQ(enc.frames_written(), 29u);
    }
    std::vector<int> want(30);
    for (int i = 0; i < 30; ++i) want[i] = i;
    EXPECT_EQ(seen, want) << threads << " thread(s)";
    EXPECT_EQ(most.load(), 1) << "the sink ran on two threads at once";
  }
}

}  // namespace
}  // namespace tumble::render
