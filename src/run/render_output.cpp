#include "run/render_output.hpp"

#include <algorithm>
#include <iostream>
#include <sstream>

#include "run/manifest_parts.hpp"
#include "base/error.hpp"
#include "base/format.hpp"
#include "io/atomic_file.hpp"
#include "io/frame_files.hpp"
#include "io/json.hpp"
#include "io/trajectory_csv.hpp"

namespace tumble::run {

namespace fs = std::filesystem;

std::string Manifest::json() const {
  auto or_null = [](const std::string& v) { return v.empty() ? io::Json(nullptr) : io::Json(v); };
  return io::json_text(io::Json{
      {"tool", "tumble"}, {"version", TUMBLE_VERSION}, {"scene", scene_path}, {"scene_name", scene_name},
      {"scene_hash", scene_hash}, {"settings_hash", settings_hash}, {"method", method}, {"step", step}, {"dt", dt},
      {"fps", fps}, {"width", frame.width}, {"height", frame.height}, {"aa", scene::antialias_name(frame.aa)},
      {"msaa", samples}, {"frame_count", frame_count},
      {"frames", {first, last}}, {"frames_written", written}, {"gl_backend", backend},
      {"gl_version", gl_version}, {"gl_renderer", gl_renderer}, {"gl_vendor", gl_vendor}, {"gl_device", gl_device},
      {"hardware_gpu", hardware_gpu}, {"video_encoder", or_null(video_encoder)}, {"video", or_null(video)},
      {"video_error", or_null(video_error)}, {"video_format", scene::video_format_name(frame.video)},
      {"crf", frame.crf()},
      {"frames_out", frames_out}, {"replacing", replacing}, {"complete", complete}});
}

namespace {
std::optional<std::string> string_field(const io::Json& j, const char* key) {
  const auto it = j.find(key);
  if (it == j.end() || !it->is_string()) return std::nullopt;
  return it->get<std::string>();
}

/// A name ending in a video format's suffix ("x.mp4", "x.gif").
bool is_video_name(const std::string& name) {
  const auto ends = [&](std::string_view e) {
    return name.size() > e.size() && name.compare(name.size() - e.size(), e.size(), e) == 0;
  };
  const auto formats = scene::video_formats();
  return std::any_of(formats.begin(), formats.end(), [&](const auto& f) { return !f.suffix.empty() && ends(f.suffix); });
}
}  // namespace

bool is_stale_temp(const std::string& name) {
  const std::string_view target = io::temp_target_name(name);
  return io::is_frame_file(std::string(target)) || target == "manifest.json" ||
         is_part_manifest(std::string(target)) || is_video_name(std::string(target));
}

std::vector<fs::path> list_dir(const fs::path& dir, bool (*pred)(const std::string&)) {
  std::vector<fs::path> out;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (pred(it->path().filename().string())) out.push_back(it->path());
  if (ec) throw io::IoError("cannot list output folder '" + dir.string() + "': " + ec.message());
  std::sort(out.begin(), out.end());
  return out;
}

void remove_file(const fs::path& p) {
  std::error_code ec;
  fs::remove(p, ec);
  if (ec) throw io::IoError("cannot remove '" + p.string() + "': " + ec.message());
}

std::string settings_hash(const scene::Scene& s, const std::string& method) {
  const scene::OutputConfig& out = s.render.output;
  std::ostringstream k;
  k << s.content_hash << '|' << method << '|' << format_number(s.simulation.step.dt) << '|' << format_number(out.fps)
    << '|' << out.width << 'x' << out.height << '|' << out.samples();
  if (out.aa == scene::Antialias::fxaa) k << "|fxaa";  // MSAA and none hash as before `aa` existed
  return scene::fnv1a_hex(k.str());
}

namespace {

/// The manifest's scene is this one's file: the same path (after resolving
/// links and ..) or the same scene name.
bool same_scene_file(const std::optional<std::string>& path, const std::optional<std::string>& name,
                     const Manifest& want) {
  if (name && !name->empty() && *name == want.scene_name) return true;
  if (!path) return false;
  std::error_code ec1, ec2;
  const fs::path a = fs::weakly_canonical(*path, ec1), b = fs::weakly_canonical(want.scene_path, ec2);
  return !ec1 && !ec2 && a == b;
}

/// --force: the old render goes, so none of its frames can pass for ours later
/// (a resumed run trusts every frame file in the folder).
void remove_render(const fs::path& dir, const std::vector<fs::path>& frames, const std::vector<std::string>& videos,
                   const std::vector<fs::path>& manifests) {
  std::cerr << "tumble: --force: removing the previous render in " << dir.string() << " (" << frames.size()
            << " frames)\n";
  for (const fs::path& f : frames) remove_file(f);
  for (const std::string& v : videos)
    if (fs::path(v).filename() == v && is_video_name(v)) remove_file(dir / v);
  for (const fs::path& m : manifests) remove_file(m);
}

}  // namespace

Existing inspect_output(const fs::path& dir, const Manifest& want, const std::string& own, bool force) {
  Existing ex;
  std::error_code ec;
  // manifest.json first, then the shards' parts: any of them may say whose folder this is.
  // Frames are listed first: a shard writes its part before its first frame,
  // so a frame seen here has its part seen below.
  const std::vector<fs::path> frames = list_dir(dir, io::is_frame_file);
  std::vector<fs::path> manifests = list_dir(dir, [](const std::string& n) { return is_part_manifest(n); });
  if (fs::exists(dir / "manifest.json", ec)) manifests.insert(manifests.begin(), dir / "manifest.json");
  std::string problem;
  std::vector<std::string> videos;
  std::size_t seen = 0;
  for (const fs::path& mpath : manifests) {
    const std::string name = mpath.filename().string();
    bool missing = false;
    const std::optional<io::Json> m = io::read_json_file(mpath, &missing);
    if (missing) continue;  // removed since it was listed (a shard beside us finished replacing it)
    ++seen;
    const std::optional<std::string> hash = m ? string_field(*m, "scene_hash") : std::nullopt;
    const std::optional<std::string> old_video = m ? string_field(*m, "video") : std::nullopt;
    if (old_video) videos.push_back(*old_video);
    const bool same_file = m && same_scene_file(string_field(*m, "scene"), string_field(*m, "scene_name"), want);
    const bool was_replacing = m && m->contains("replacing") && (*m)["replacing"] == true;
    if (!m || string_field(*m, "tool") != std::optional<std::string>("tumble") || !hash) {
      problem = "holds a " + name + " that tumble did not write";
      break;
    }
    if (*hash != want.scene_hash && !same_file) {
      problem = "holds a render of another scene (" + string_field(*m, "scene").value_or("?") + ", hash " + *hash +
                "; this scene's hash is " + want.scene_hash + ")";
      break;
    }
    if (*hash != want.scene_hash || string_field(*m, "settings_hash") != want.settings_hash || was_replacing) {
      // The edit loop: the same scene file, changed (or other settings, or a
      // replacement that was interrupted). Its frames are replaced, not trusted.
      ex.replacing = true;
      if (old_video && name == "manifest.json") ex.old_video = *old_video;
    } else if (name == own) {
      ex.resumable = true;
      const auto r = m->find("frames");  // [A, B]
      if (r != m->end() && r->is_array() && r->size() == 2 && (*r)[0].is_number_integer() &&
          (*r)[1].is_number_integer())
        ex.first = (*r)[0].get<long>(), ex.last = (*r)[1].get<long>();
    }
  }
  if (seen == 0 && !frames.empty())
    problem = "holds " + std::to_string(frames.size()) + " frame_*.png file(s) but no manifest.json";
  if (problem.empty()) {
    if (ex.replacing) ex.resumable = false, ex.first = 0, ex.last = -1;
    return ex;
  }
  if (!force)
    throw InputError("tumble: output folder " + dir.string() + " " + problem +
                     ".\ntumble: choose another folder with -o, or add --force to replace that render");
  remove_render(dir, frames, videos, manifests);
  return {};
}

void remove_stale(const fs::path& dir, const Existing& ex, const std::string& settings_hash, const std::string& own,
                  long first, long last, const std::string& keep_video) {
  if (!ex.replacing) return;
  // Frames of shards with our settings stay (they may be rendering now: each
  // writes its part before its first frame); parts of other settings go.
  std::vector<std::pair<long, long>> keep = {{first, last}};
  for (const Part& p : read_parts(dir)) {
    if (p.ok && p.settings_hash == settings_hash) keep.emplace_back(p.first, p.last);
    else if (p.file != own) remove_file(dir / p.file);
  }
  for (const fs::path& f : list_dir(dir, io::is_frame_file)) {
    const long k = *io::frame_index(f.filename().string());
    if (std::none_of(keep.begin(), keep.end(), [k](const auto& r) { return k >= r.first && k <= r.second; }))
      remove_file(f);
  }
  if (!ex.old_video.empty() && ex.old_video != keep_video && fs::path(ex.old_video).filename() == ex.old_video &&
      ex.old_video != "manifest.json" && is_video_name(ex.old_video))
    remove_file(dir / ex.old_video);
  // A shard leaves manifest.json to `assemble`; an earlier render's is no longer true.
  if (own != "manifest.json") {
    std::error_code ec;
    if (fs::exists(dir / "manifest.json", ec)) {
      const Part m = read_part(dir / "manifest.json");
      if (!m.ok || m.settings_hash != settings_hash) remove_file(dir / "manifest.json");
    }
  }
}

std::string video_file_name(const std::string& scene_name, scene::VideoFormat f) {
  // The loader restricts names to [A-Za-z0-9_.-]; still, never leave the folder.
  std::string base = scene_name;
  if (base.empty() || fs::path(base).filename() != base || base == "." || base == "..") base = "video";
  return base + std::string(scene::video_format(f).suffix);
}

std::string video_file_name(const scene::Scene& s, scene::VideoFormat f) { return video_file_name(s.name, f); }

}  // namespace tumble::run
