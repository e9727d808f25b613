#include "run/render_stream.hpp"

#include <algorithm>
#include <cmath>
#include <csignal>

#include "compose/layout_notes.hpp"
#include "io/atomic_file.hpp"
#include "render/frame_encoder.hpp"
#include "run/video_stream.hpp"

namespace tumble::run {

Streamed stream_frames(render::Renderer& renderer, const compose::FrameBuilder& builder, long count, VideoStream& stream,
                       int jobs, const StopPoll& stop, const std::function<void(long)>& advance,
                       compose::LayoutNotes* notes) {
  Streamed s;
  // The sink polls `stop` while ffmpeg's pipe is full: once a signal came,
  // every write returns at once, so the queue drains and the loop sees it.
  render::FrameEncoder encoder(jobs, 0, render::FrameEncoder::OrderedSink{[&](const io::Image& img) {
                                 stream.write(img, stop);
                               }});
  render::RawFrame raw;  // a finished frame's buffer, recycled: no page faults per frame
  auto submit = [&] {
    encoder.submit(std::move(raw));
    raw = encoder.recycle_raw();
  };
  for (; s.frames < count; ++s.frames) {
    if ((s.signal = stop ? stop() : 0) != 0 || stream.broken()) break;
    const viz::DrawList dl = builder.build(s.frames);
    if (notes) notes->add(s.frames, dl.notes);
    if (renderer.render_overlapped(dl, s.frames, raw)) submit();
    if (advance) advance(s.frames + 1);
  }
  if (renderer.finish_overlapped(raw)) submit();  // on a GPU: the last frame read back
  encoder.flush();
  if (s.signal == 0 && stop) s.signal = stop();  // arrived during the last frames
  return s;
}

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
  compose::LayoutNotes notes;
  const Streamed s = stream_frames(j.renderer, j.builder, std::min(count, j.good), stream, j.jobs, stop,
                                   [&](long n) { l.advance(n); }, &notes);
  l.end();
  warn_layout(notes, l);
  const long k = s.frames;
  const VideoResult v = s.signal != 0 ? stream.abort(s.signal) : stream.finish(stop);
  if (!v.ok()) {
    man.video_error = v.message;
    save();
    l.note(v.message);
    if (v.status != VideoResult::interrupted) return {Outcome::failed, 0, {}};
    const int signal = v.signal;
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
