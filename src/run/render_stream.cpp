#include "run/render_stream.hpp"

#include <cmath>
#include <csignal>

#include "io/atomic_file.hpp"
#include "run/video_stream.hpp"

namespace tumble::run {

Outcome stream_render(const StreamJob& j) {
  Manifest& man = j.manifest;
  Listener& l = j.listener;
  const scene::OutputConfig& out = j.scene.render.output;
  const long count = man.frame_count;
  const std::filesystem::path video = j.dir / video_file_name(j.scene, out.video);
  auto save = [&] { io::atomic_write_file(j.dir / "manifest.json", man.json()); };
  const StopPoll stop = [&] { return l.stop(); };
  VideoStream stream(out.width, out.height, static_cast<int>(std::lround(out.fps)), out.video, out.crf(), video,
                     j.encoder);
  if (!stream.running()) {
    man.video_error = stream.status().message;
    save();
    l.note(man.video_error);
    return {Outcome::failed, 0, {}};
  }
  l.begin(count);
  int signal = 0;
  long k = 0;
  io::Image img;  // one buffer: ffmpeg has read a frame once write() returns
  for (; k < count && k < j.good; ++k) {
    if ((signal = stop()) != 0) break;
    j.renderer.render(j.builder.build(k), img);
    if ((signal = stream.write(img, stop)) != 0 || stream.broken()) break;
    l.advance(k + 1);
  }
  l.end();
  if (signal == 0) signal = stop();
  const VideoResult v = signal != 0 ? stream.abort(signal) : stream.finish();
  if (!v.ok()) {
    man.video_error = v.message;
    save();
    l.note(v.message);
    if (signal == 0) return {Outcome::failed, 0, {}};
    l.note(std::string("interrupted (") + (signal == SIGINT ? "SIGINT" : "SIGTERM") +
           "): a streamed render keeps no frames, so there is nothing to resume; run it again: " + j.rerun);
    return {Outcome::interrupted, signal, {}};
  }
  man.written = k;
  man.video = video.filename().string();
  if (k < count) {  // diverged: the video holds the frames computed before
    save();
    l.note(j.diverged);
    l.note(video.string() + " holds the " + std::to_string(k) + " frames before");
    return {Outcome::diverged, 0, {}};
  }
  // A replaced render's frames are not this one's: none of them may stay.
  remove_stale(j.dir, j.existing, man.settings_hash, "manifest.json", 0, -1, man.video);
  man.replacing = false;
  man.complete = true;
  save();
  return {Outcome::done, 0,
          "streamed frames 0.." + std::to_string(count - 1) + " of " + std::to_string(count) + " into " + video.string()};
}

}  // namespace tumble::run
