#include "run/assemble.hpp"

#include <cmath>

#include "base/error.hpp"
#include "base/format.hpp"
#include "io/atomic_file.hpp"
#include "io/folder_lock.hpp"
#include "io/frame_files.hpp"
#include "io/frame_sums.hpp"
#include "run/manifest_parts.hpp"
#include "run/render_output.hpp"
#include "run/video.hpp"

namespace tumble::run {

namespace {

namespace fs = std::filesystem;

std::string describe(const Part& p) {
  return "scene hash " + p.scene_hash + ", settings hash " + p.settings_hash + ", " +
         std::to_string(p.frame_count) + " frames of " + std::to_string(p.width) + "x" + std::to_string(p.height) +
         " at " + format_number(p.fps) + " fps, video " + p.video_format + " at CRF " + std::to_string(p.crf);
}

/// Every reason the parts do not make one whole render (empty when they do):
/// a part of another render (hashes, frame count, video settings differ from
/// `ref`), an incomplete part, frames that no complete part covers or whose
/// file is gone. Overlaps of agreeing parts are fine: same settings, same pixels.
std::vector<std::string> check_parts(const fs::path& dir, const std::vector<Part>& parts, const Part& ref) {
  std::vector<std::string> errors;
  std::vector<char> have(static_cast<std::size_t>(ref.frame_count), 0);
  const auto sums = io::read_frame_sums(dir);
  long damaged = 0;
  for (const Part& p : parts) {
    if (!p.ok) {
      errors.push_back(p.file + ": not a manifest part written by tumble (" +
                       (p.bad_field.empty() ? std::string("unreadable, or not JSON") : p.bad_field) + ")");
    } else if (describe(p) != describe(ref)) {
      errors.push_back(p.file + " (" + describe(p) + ") is not a shard of the same render as " + ref.file + " (" +
                       describe(ref) + "); render its frames again with the same scene and options, or remove it");
    } else if (!p.complete) {
      errors.push_back(p.file + ": incomplete (" + std::to_string(p.written) + " of " +
                       std::to_string(p.last - p.first + 1) + " frames written); finish it with tumble render " +
                       p.json.value("scene", "SCENE") + " -o " + dir.string() + " --frames " + std::to_string(p.first) +
                       ":" + std::to_string(p.last) + " --resume");
    } else {
      // Each frame must be what its shard recorded when it wrote it (io/frame_sums.hpp).
      const int w = ref.width, h = ref.height;
      for (long k = std::max(0L, p.first); k <= p.last && k < ref.frame_count; ++k) {
        if (have[static_cast<std::size_t>(k)]) continue;
        const std::string why = io::check_frame(io::frame_path(dir, k), sums, w, h);
        have[static_cast<std::size_t>(k)] = why.empty() ? 1 : 0;
        if (!why.empty() && why != "missing" && ++damaged <= 5)
          errors.push_back(io::frame_path(dir, k).filename().string() + " fails its check: " + why);
      }
    }
  }
  std::vector<std::pair<long, long>> covered;
  for (long k = 0; k < ref.frame_count; ++k)
    if (have[static_cast<std::size_t>(k)]) covered.emplace_back(k, k);
  if (const std::string gaps = missing_ranges(covered, ref.frame_count); !gaps.empty())
    errors.push_back("frames " + gaps + " of 0:" + std::to_string(ref.frame_count - 1) +
                     " are missing (no complete part covers them, or their files are gone or damaged); render them with "
                     "--frames A:B");
  return errors;
}

/// The parts in `dir`, and the first readable one; a folder holding none that
/// tumble wrote is not a shards folder. Only reads, so it runs before the lock.
std::pair<std::vector<Part>, std::size_t> tumble_parts(const fs::path& dir) {
  std::vector<Part> parts = read_parts(dir);
  if (parts.empty())
    throw InputError("tumble assemble: " + dir.string() +
                     " holds no manifest.part-*.json; render the shards first with tumble render SCENE -o " +
                     dir.string() + " --frames A:B");
  std::size_t ref = 0;
  while (ref < parts.size() && !parts[ref].ok) ++ref;
  if (ref == parts.size()) {
    std::string why;
    for (const Part& p : parts) why += "\n  " + p.file + ": " + (p.bad_field.empty() ? "unreadable, or not JSON" : p.bad_field);
    throw InputError("tumble assemble: no manifest part in " + dir.string() + " was written by tumble:" + why);
  }
  return {std::move(parts), ref};
}

/// The parts in `dir` and the first readable one, which the others must agree with.
std::pair<std::vector<Part>, std::size_t> whole_render_parts(const fs::path& dir) {
  // Alone in the folder (the caller holds it exclusively): every temp file is
  // a killed run's leftover (a video half encoded, say).
  for (const fs::path& t : list_dir(dir, is_stale_temp)) remove_file(t);
  auto [parts, ref] = tumble_parts(dir);
  if (const std::vector<std::string> errors = check_parts(dir, parts, parts[ref]); !errors.empty()) {
    std::string msg = "tumble assemble: the shards in " + dir.string() + " do not make a whole render:";
    for (const std::string& e : errors) msg += "\n  " + e;
    throw InputError(msg);
  }
  return {std::move(parts), ref};
}

}  // namespace

Outcome assemble(const fs::path& dir, std::optional<scene::VideoFormat> video, Listener& l) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw io::IoError("'" + dir.string() + "' is not a folder");
  try {  // a foreign folder gets no lock file: check first (a read), then lock, then check all
    (void)tumble_parts(dir);
  } catch (const InputError&) {
    (void)io::FolderLock::refuse_if_held(dir);  // a first shard may still be writing its part
    throw;
  }
  const io::FolderLock lock(dir, io::FolderLock::Mode::exclusive, "tumble assemble", "");  // no shard may run meanwhile
  const auto [parts, ref_index] = whole_render_parts(dir);
  const Part& ref = parts[ref_index];
  const long count = ref.frame_count;
  // An earlier, longer render's frames past the end are not part of this one.
  for (const fs::path& f : list_dir(dir, io::is_frame_file))
    if (*io::frame_index(f.filename().string()) >= count) remove_file(f);

  io::Json man = ref.json;
  man["frames"] = {0, count - 1};
  man["frames_written"] = count;
  man["video"] = nullptr;
  man["video_error"] = nullptr;
  man["replacing"] = false;
  man["complete"] = false;
  man["assembled_from"] = io::Json::array();
  for (const Part& p : parts) man["assembled_from"].push_back(p.file);
  const std::string format = video ? std::string(scene::video_format_name(*video)) : ref.video_format;
  man["video_format"] = format;
  const fs::path mpath = dir / "manifest.json";
  l.arm_stop();
  std::string video_name;
  if (format != "none") {
    const scene::VideoFormat f = scene::parse_video_format(format).value_or(scene::VideoFormat::gif);
    video_name = video_file_name(man.value("scene_name", std::string()), f);
    io::write_json_atomic(mpath, man);  // "complete": false until the video exists
    l.begin(count);
    const VideoResult v =
        encode_video(dir, static_cast<int>(std::lround(ref.fps)), f, ref.crf, dir / video_name,
                     [&] { return l.stop(); }, [&](long n) { l.advance(std::min(n, count)); });
    l.end();
    if (!v.ok()) {
      man["video_error"] = v.message;
      io::write_json_atomic(mpath, man);
      l.note(v.message);
      l.note("the parts are kept; run tumble assemble " + dir.string() + " again");
      return {v.status == VideoResult::interrupted ? Outcome::interrupted : Outcome::failed, v.signal, {}};
    }
    man["video"] = video_name;
  }
  man["complete"] = true;
  io::write_json_atomic(mpath, man);
  // manifest.json now records the whole render (and lists the parts it came from).
  for (const Part& p : parts) remove_file(dir / p.file);
  return {Outcome::done, 0,
          "assembled frames 0.." + std::to_string(count - 1) + " from " + std::to_string(parts.size()) + " parts in " +
              dir.string() + (video_name.empty() ? "" : " (video " + video_name + ")")};
}

}  // namespace tumble::run
