#include "run/render_folder.hpp"

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <map>
#include <memory>
#include <stdexcept>

#include "base/error.hpp"
#include "base/format.hpp"
#include "io/atomic_file.hpp"
#include "io/folder_lock.hpp"
#include "io/frame_files.hpp"
#include "io/frame_sums.hpp"
#include "io/trajectory_csv.hpp"
#include "render/frame_encoder.hpp"
#include "render/renderer.hpp"
#include "render/worker_threads.hpp"
#include "run/manifest_parts.hpp"
#include "compose/frame_builder.hpp"
#include "compose/layout_notes.hpp"
#include "run/frame_range.hpp"
#include "run/render_output.hpp"
#include "run/render_stream.hpp"
#include "run/video.hpp"

namespace tumble::run {

namespace fs = std::filesystem;

std::string quote_arg(const std::string& a) {
  if (a.find_first_of(" '\"\\$`") == std::string::npos) return a;
  std::string q = "'";
  for (char c : a) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

void warn_layout(const compose::LayoutNotes& notes, Listener& l) {
  for (const std::string& line : notes.lines()) l.note("warning: " + line);
}

namespace {

void make_folder(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw io::IoError("cannot create output folder '" + dir.string() + "': " + ec.message());
  if (!fs::is_directory(dir, ec)) throw io::IoError("output path '" + dir.string() + "' is not a folder");
}

/// The methods that change the pixels, for the settings hash: [compare]'s, or
/// each body's pick (auto with a tolerance: the pick follows from the scene
/// bytes, hashed, and the tolerance).
std::string method_key(const scene::Scene& s) {
  std::vector<std::string> labels;
  if (!s.render.compare_methods.empty())
    for (Method m : s.render.compare_methods) labels.emplace_back(method_name(m));
  else
    for (const scene::Body& b : s.bodies) {
      const std::string n = s.simulation.automatic && s.simulation.tolerance
                                ? "auto@" + format_number(*s.simulation.tolerance)
                                : std::string(method_name(scene::step_config(s.simulation, b.model).method));
      if (std::find(labels.begin(), labels.end(), n) == labels.end()) labels.push_back(n);
    }
  std::string key;
  for (const auto& l : labels) key += l + ",";
  return key;
}

/// One render's folder, range and manifest, shared by the steps below.
struct Job {
  Job(const RenderRequest& r, Listener& listener) : req(r), l(listener) {}
  const RenderRequest& req;
  Listener& l;
  long count = 0, first = 0, last = -1;
  bool shard = false, resume = false;
  std::string own;  ///< manifest.json, or this shard's part
  Existing existing;
  Manifest man;
  std::unique_ptr<io::FolderLock> lock;  ///< held from open_folder to the end
  compose::LayoutNotes notes;            ///< what the layout left out of the frames drawn
  fs::path man_path() const { return req.dir / own; }
  void save() const { io::atomic_write_file(man_path(), man.json()); }
  /// "tumble render SCENE -o DIR" + `tail`: how to run this again.
  std::string rerun(const std::string& tail) const {
    if (req.rerun) return req.rerun(tail);
    return "tumble render " + quote_arg(req.scene_arg) + " -o " + quote_arg(req.dir.string()) + tail;
  }
};

/// The folder checked against the render it holds (inspect_output), the range
/// chosen (a resumed render continues its own), dead temp files removed.
void open_folder(Job& j) {
  const scene::Scene& s = j.req.scene;
  const std::pair<long, long> asked =
      j.req.frames.empty() ? std::pair<long, long>{0, j.count - 1} : parse_frame_range(j.req.frames, j.count);
  j.man.scene_path = s.path.string();
  j.man.scene_name = s.name;
  j.man.scene_hash = s.content_hash;
  j.man.settings_hash = settings_hash(s, method_key(s));
  // A shard (a range short of the whole render) records itself in its own
  // part, so shards running at once never overwrite each other's manifest.
  j.shard = asked.first != 0 || asked.second != j.count - 1;
  j.own = j.shard ? part_manifest_name(asked.first, asked.second) : "manifest.json";
  // No output may replace an input (a scene file named like the video, say):
  // refused before anything in the folder changes.
  io::check_output_target(j.req.dir / j.own, "the manifest");
  if (s.render.output.video != scene::VideoFormat::none)
    io::check_output_target(j.req.dir / video_file_name(s, s.render.output.video), "the video");
  // Nothing is written into a folder that is refused (not even the lock file):
  // check it first (a read), then lock, then check again under the lock.
  std::error_code ec;
  const std::string key = j.man.scene_hash + " " + j.man.settings_hash;
  if (!j.req.force && fs::is_directory(j.req.dir, ec)) try {
      (void)inspect_output(j.req.dir, j.man, j.own, false);
    } catch (const InputError&) {
      // Foreign-looking because its writer is mid-way: refused as in use, unless
      // that writer is a shard of this very render (then check again under the lock).
      if (io::FolderLock::refuse_if_held(j.req.dir, j.shard ? key : "") != io::FolderLock::Holder::siblings) throw;
    }
  make_folder(j.req.dir);
  // One writer per folder; the shards of one render (same scene and settings) together.
  j.lock = std::make_unique<io::FolderLock>(
      j.req.dir, j.shard ? io::FolderLock::Mode::shared : io::FolderLock::Mode::exclusive,
      "tumble render " + quote_arg(j.req.scene_arg) + (j.shard ? " --frames " + j.req.frames : std::string()), key);
  j.existing = inspect_output(j.req.dir, j.man, j.own, j.req.force);
  const Existing& ex = j.existing;
  std::tie(j.first, j.last) = asked;
  if (j.req.frames.empty() && j.req.resume && ex.resumable && ex.first >= 0 && ex.last < j.count && ex.first <= ex.last)
    std::tie(j.first, j.last) = std::pair{ex.first, ex.last};  // continue the range that was being rendered
  j.resume = j.req.resume && ex.resumable;
  j.man.replacing = ex.replacing;
  if (ex.replacing)
    j.l.note("replacing the earlier render of " + s.name + " in " + j.req.dir.string() +
             " (scene or settings changed): frames are overwritten one by one, the rest removed at the end");
  // A process killed mid-write leaves its temp files; they are never valid output.
  // A shard removes only its own: the others' in-flight temp files look the same.
  for (const fs::path& t : list_dir(j.req.dir, is_stale_temp)) {
    const std::string target(io::temp_target_name(t.filename().string()));
    const long k = io::frame_index(target).value_or(-1);
    if (!j.shard || target == j.own || (k >= j.first && k <= j.last)) remove_file(t);
  }
}

/// What the manifest records of the runs, the GL context and the frames.
void describe(Job& j, const std::vector<scene::Run>& runs, const render::GlContext& ctx, int samples,
              const VideoEncoder& encoder) {
  const scene::Scene& s = j.req.scene;
  Manifest& man = j.man;
  for (const scene::Run& r : runs) man.method += (man.method.empty() ? "" : ",") + r.label;
  for (const scene::Run& r : runs) man.step += (man.step.empty() ? "" : ",") + r.step_label;
  man.dt = s.simulation.step.dt;
  man.fps = s.render.output.fps;
  man.frame = s.render.output;
  man.samples = samples;
  man.frame_count = j.count;
  man.first = j.first;
  man.last = j.last;
  man.gl_version = ctx.version();
  man.gl_renderer = ctx.renderer();
  man.backend = std::string(render::to_string(j.req.backend));
  man.gl_vendor = ctx.vendor();
  man.gl_device = ctx.display();
  man.hardware_gpu = ctx.hardware_gpu();
  if (scene::video_format(s.render.output.video).h264) man.video_encoder = encoder.codec + " " + encoder.preset;
  man.frames_out = j.req.stream ? "none" : "png";
}

/// Frames of this run's range now on disk (a replacing render counts only its own).
long on_disk(const Job& j, long drawn) {
  if (j.man.replacing) return drawn;  // the earlier render's frames are not ours
  std::error_code ec;
  long n = 0;
  for (long k = j.first; k <= j.last; ++k) n += fs::exists(io::frame_path(j.req.dir, k), ec) ? 1 : 0;
  return n;
}

struct Drawn {
  long drawn = 0, skipped = 0, rejected = 0;
  int signal = 0;
};

/// A test seam (tests/app/soak_test.cpp): TUMBLE_TEST_STOP_AT_FRAME=k stops
/// the process (SIGSTOP) as it reaches frame k, so a test can kill it at a
/// known frame, whatever the machine's load, with the encoder's threads
/// caught wherever they are (mid-encode, mid-write, mid-rename). -1: unset.
long test_stop_frame() {
  const char* v = std::getenv("TUMBLE_TEST_STOP_AT_FRAME");
  return v && *v ? std::atol(v) : -1;
}

/// Draws first..last (up to `good`, where the simulation stopped) into PNG
/// files, skipping those a resumed render already has. A frame that cannot be
/// written (disk full) records what is on disk and throws io::IoError.
Drawn draw_frames(Job& j, const compose::FrameBuilder& builder, render::Renderer& renderer, long good) {
  Drawn d;
  std::error_code ec;
  // A frame on disk is kept only if it is what was recorded when written (io/frame_sums.hpp).
  const auto sums = j.resume ? io::read_frame_sums(j.req.dir) : std::map<std::string, io::FrameSum>{};
  const scene::OutputConfig& out = j.req.scene.render.output;
  auto kept = [&](long k) {
    const fs::path f = io::frame_path(j.req.dir, k);
    if (!fs::exists(fs::symlink_status(f, ec))) return false;
    if (io::check_frame(f, sums, out.width, out.height).empty()) return true;
    ++d.rejected;
    remove_file(f);  // a link goes, not what it points to
    return false;
  };
  j.l.begin(j.last - j.first + 1);
  try {
    render::FrameEncoder encoder(j.req.jobs, 0, [](const fs::path& f) { io::record_frame(f); });
    // Reuse a written frame's buffer: a fresh 3.7 MB buffer per frame costs
    // page faults. The encoder's threads finish it (FXAA) while we draw on;
    // on a GPU the read-back itself overlaps the next frame (one frame late).
    render::RawFrame raw;
    auto submit = [&] {
      const fs::path path = io::frame_path(j.req.dir, raw.index);
      encoder.submit(path, std::move(raw));
      raw = encoder.recycle_raw();
    };
    const long stop_at = test_stop_frame();
    for (long k = j.first; k <= j.last && k < good; ++k) {
      if (k == stop_at) ::raise(SIGSTOP);
      if ((d.signal = j.l.stop()) != 0) break;
      if (j.resume && kept(k)) {
        ++d.skipped;  // written whole by an earlier run (rename is atomic) and unchanged since
      } else {
        const viz::DrawList dl = builder.build(k);
        j.notes.add(k, dl.notes);
        if (renderer.render_overlapped(dl, k, raw)) submit();
        ++d.drawn;
      }
      j.l.advance(k - j.first + 1);
    }
    if (renderer.finish_overlapped(raw)) submit();
    encoder.flush();  // the frames in flight are finished, not dropped
  } catch (const std::runtime_error& e) {  // a frame could not be written: disk full, permissions
    j.man.written = on_disk(j, d.drawn);
    try {
      j.save();
    } catch (const std::exception&) {  // the disk that failed the frame may fail this too
    }
    throw io::IoError(e.what());
  }
  j.l.end();
  warn_layout(j.notes, j.l);
  if (d.rejected > 0)
    j.l.note(std::to_string(d.rejected) + " frame(s) on disk failed their check (truncated, changed, a link, or not "
             "recorded in " + io::kFrameSumsName + ") and were drawn again");
  if (d.signal == 0) d.signal = j.l.stop();  // arrived during the last frames: they are whole anyway
  return d;
}

/// A range cut short by a stop request or a divergence: the manifest says
/// what is on disk and "complete": false.
Outcome stopped_early(Job& j, int signal, const std::string& diverged) {
  j.man.complete = false;
  j.save();
  if (signal != 0) {
    j.l.note(std::string("interrupted (") + (signal == SIGINT ? "SIGINT" : "SIGTERM") + "): kept " +
             std::to_string(j.man.written) + " of " + std::to_string(j.last - j.first + 1) + " frames in " +
             j.req.dir.string());
    j.l.note("continue with: " + j.rerun((j.shard ? " --frames " + j.req.frames : std::string()) + " --resume"));
    return {Outcome::interrupted, signal, {}};
  }
  j.l.note(diverged);
  j.l.note("kept " + std::to_string(j.man.written) + " frames in " + j.req.dir.string());
  return {Outcome::diverged, 0, {}};
}

/// The video from the frames on disk, part of a complete render: until it
/// exists the manifest says "complete": false, and --resume makes it.
Outcome encode_frames(Job& j, const VideoEncoder& encoder) {
  const scene::OutputConfig& out = j.req.scene.render.output;
  const fs::path video = j.req.dir / video_file_name(j.req.scene, out.video);
  j.l.begin(j.count, "encoding " + video.filename().string() + " from " + std::to_string(j.count) + " frames");
  const VideoResult v = encode_video(
      j.req.dir, static_cast<int>(std::lround(out.fps)), out.video, out.crf(), video, [&] { return j.l.stop(); },
      [&](long n) { j.l.advance(std::min(n, j.count)); }, encoder);
  j.l.end();
  if (!v.ok()) {
    j.man.complete = false;
    j.man.video_error = v.message;
    j.save();
    j.l.note(v.message);
    j.l.note("all " + std::to_string(j.count) + " frames are in " + j.req.dir.string() +
             "; make the video with: " + j.rerun(" --resume"));
    return v.status == VideoResult::interrupted ? Outcome{Outcome::interrupted, v.signal, {}}
                                                : Outcome{Outcome::failed, 0, {}};
  }
  j.man.video = video.filename().string();
  return {};
}

/// After the frames: the earlier render's leftovers removed, the video made
/// (a shard's is made by `tumble assemble`), the manifest completed.
Outcome finish(Job& j, const Drawn& d, const VideoEncoder& encoder) {
  const scene::OutputConfig& out = j.req.scene.render.output;
  // Every new frame exists: the earlier render's other frames can go (before
  // the encode, which would read a stale frame past the last as one of ours).
  // A shard makes no video, so the earlier render's (same name or not) goes too.
  const bool video = !j.shard && out.video != scene::VideoFormat::none;
  remove_stale(j.req.dir, j.existing, j.man.settings_hash, j.own, j.first, j.last,
               video ? video_file_name(j.req.scene, out.video) : std::string());
  j.man.replacing = false;
  if (video)
    if (Outcome o = encode_frames(j, encoder); o.kind != Outcome::done) return o;
  j.save();
  return {Outcome::done, 0,
          "rendered frames " + std::to_string(j.first) + ".." + std::to_string(j.last) + " of " +
              std::to_string(j.count) + " into " + j.req.dir.string() +
              (d.skipped ? " (" + std::to_string(d.skipped) + " already on disk)" : std::string()) +
              (j.man.video.empty() ? "" : " (video " + j.man.video + ")")};
}

}  // namespace

Outcome render_scene(const RenderRequest& r, Listener& l) {
  const scene::Scene& s = r.scene;
  const scene::OutputConfig& out = s.render.output;
  Job j{r, l};
  j.count = scene::frame_clock(s, out.fps).count();
  open_folder(j);
  const std::vector<scene::Run> runs = scene::simulate_runs(s, j.count, out.fps);
  for (const scene::Run& run : runs)
    for (const std::string& note : run.auto_notes) l.note(note);
  const compose::FrameBuilder builder(s, runs, out.fps, out.width, out.height);
  // Frames every run could reach (a single run stops at its divergence).
  const long good = runs.size() == 1 ? static_cast<long>(runs[0].frames.size()) : j.count;
  const std::string diverged = runs[0].diverged.value_or("stopped early");
  std::unique_ptr<render::GlContext> ctx;
  try {
    ctx = render::create_gl_context(r.backend, r.gpu);
  } catch (const std::invalid_argument& e) {  // --gpu / TUMBLE_EGL_DEVICE past the last device
    throw InputError(e.what());
  }
  render::Renderer renderer(*ctx, out.width, out.height, out.aa, out.msaa);
  const VideoEncoder encoder = scene::video_format(out.video).h264
                                   ? choose_video_encoder(ctx->vendor(), render::usable_cores())
                                   : VideoEncoder{};
  describe(j, runs, *ctx, renderer.samples(), encoder);
  // Every frame is written again; gone only now that GL (and its settings) work.
  if (!j.resume && !j.shard) remove_file(j.req.dir / io::kFrameSumsName);
  l.arm_stop();
  if (r.stream) {
    j.save();
    return stream_render({r.dir, s, builder, renderer, j.man, j.existing, good, l,
                          j.rerun(" --frames-out none"), diverged, encoder, r.jobs});
  }
  if (j.resume) j.man.written = on_disk(j, 0);
  j.save();
  const Drawn d = draw_frames(j, builder, renderer, good);
  j.man.written = on_disk(j, d.drawn);
  j.man.complete = j.man.written == j.last - j.first + 1;
  if (!j.man.complete || d.signal != 0) return stopped_early(j, d.signal, diverged);
  return finish(j, d, encoder);
}

}  // namespace tumble::run
