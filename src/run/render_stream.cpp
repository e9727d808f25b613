#include "app/render_stream.hpp"

#include <cmath>
#include <csignal>
#include <iostream>

#include "app/commands.hpp"
#include "app/progress.hpp"
#include "app/video_stream.hpp"
#include "io/atomic_file.hpp"

namespace tumble::app {

int stream_render(const StreamJob& j) {
  Manifest& man = j.manifest;
  const scene::OutputConfig& out = j.scene.render.output;
  const long count = man.frame_count;
  const std::filesystem::path video = j.dir / video_file_name(j.scene, out.video);
  auto save = [&] { io::atomic_write_file(j.dir / "manifest.json", man.json()); };
  VideoStream stream(out.width, out.height, static_cast<int>(std::lround(out.fps)), out.video, man.crf, video);
  if (!stream.running()) {
    man.video_error = stream.status().message;
    save();
    std::cerr << "tumble: " << man.video_error << "\n";
    return kRuntimeError;
  }
  Progress progress(count, j.progress);
  int signal = 0;
  long k = 0;
  io::Image img;  // one buffer: ffmpeg has read a frame once write() returns
  for (; k < count && k < j.good; ++k) {
    if ((signal = j.stop()) != 0) break;
    j.renderer.render(j.builder.build(k), img);
    if ((signal = stream.write(img, j.stop)) != 0 || stream.broken()) break;
    progress.update(k + 1);
  }
  progress.finish();
  if (signal == 0) signal = j.stop();
  const VideoResult v = signal != 0 ? stream.abort(signal) : stream.finish();
  if (!v.ok()) {
    man.video_error = v.message;
    save();
    std::cerr << "tumble: " << v.message << "\n";
    if (signal != 0) {
      std::cerr << "tumble: interrupted (" << (signal == SIGINT ? "SIGINT" : "SIGTERM")
                << "): a streamed render keeps no frames, so there is nothing to resume; run it again: " << j.rerun
                << "\n";
      return 128 + signal;
    }
    return kRuntimeError;
  }
  man.written = k;
  man.video = video.filename().string();
  if (k < count) {  // diverged: the video holds the frames computed before
    save();
    std::cerr << "tumble: " << j.diverged << "\n"
              << "tumble: " << video.string() << " holds the " << k << " frames before\n";
    return kDiverged;
  }
  // A replaced render's frames are not this one's: none of them may stay.
  remove_stale(j.dir, j.existing, man.settings_hash, "manifest.json", 0, -1, man.video);
  man.replacing = false;
  man.complete = true;
  save();
  std::cout << "streamed frames 0.." << count - 1 << " of " << count << " into " << video.string() << "\n";
  return kOk;
}

}  // namespace tumble::app
