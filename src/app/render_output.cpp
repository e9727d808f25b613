#include "app/render_output.hpp"

#include <algorithm>
#include <iostream>
#include <sstream>

#include "app/commands.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/frame_files.hpp"
#include "io/json.hpp"

namespace tumble::app {

namespace fs = std::filesystem;

std::string Manifest::json() const {
  return io::json_text(io::Json{
      {"tool", "tumble"}, {"version", TUMBLE_VERSION}, {"scene", scene_path}, {"scene_hash", scene_hash},
      {"settings_hash", settings_hash}, {"method", method}, {"step", step}, {"dt", dt}, {"fps", fps},
      {"width", width}, {"height", height}, {"msaa", msaa}, {"frame_count", frame_count},
      {"frames", {first, last}}, {"frames_written", written}, {"gl_backend", backend},
      {"gl_version", gl_version}, {"gl_renderer", gl_renderer}, {"video", video}, {"complete", complete}});
}

namespace {
std::optional<std::string> string_field(const io::Json& j, const char* key) {
  const auto it = j.find(key);
  if (it == j.end() || !it->is_string()) return std::nullopt;
  return it->get<std::string>();
}
}  // namespace

bool is_stale_temp(const std::string& name) {
  const std::string_view target = io::temp_target_name(name);
  const auto ends_with = [&](std::string_view ext) {
    return target.size() > ext.size() && target.substr(target.size() - ext.size()) == ext;
  };
  return io::is_frame_file(std::string(target)) || target == "manifest.json" || ends_with(".mp4") ||
         ends_with(".gif");
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
  k << s.content_hash << '|' << method << '|' << format_double(s.simulation.dt) << '|' << format_double(out.fps)
    << '|' << out.width << 'x' << out.height << '|' << out.msaa;
  return scene::fnv1a_hex(k.str());
}

Existing inspect_output(const fs::path& dir, const Manifest& want, bool force) {
  Existing ex;
  const fs::path mpath = dir / "manifest.json";
  std::error_code ec;
  const bool has_manifest = fs::exists(mpath, ec);
  const std::vector<fs::path> frames = list_dir(dir, io::is_frame_file);
  std::string problem;
  std::optional<std::string> old_video;
  if (has_manifest) {
    const std::optional<io::Json> m = io::read_json_file(mpath);
    const std::optional<std::string> hash = m ? string_field(*m, "scene_hash") : std::nullopt;
    if (m) old_video = string_field(*m, "video");
    if (!m || string_field(*m, "tool") != std::optional<std::string>("tumble") || !hash) {
      problem = "holds a manifest.json that tumble did not write";
    } else if (*hash != want.scene_hash) {
      problem = "holds a render of another scene (" + string_field(*m, "scene").value_or("?") + ", hash " + *hash +
                "; this scene's hash is " + want.scene_hash + ")";
    } else if (string_field(*m, "settings_hash") != want.settings_hash) {
      problem = "holds a render of this scene with other settings (size, fps, msaa, method or dt)";
    } else {
      ex.resumable = true;
      const auto r = m->find("frames");  // [A, B]
      if (r != m->end() && r->is_array() && r->size() == 2 && (*r)[0].is_number_integer() &&
          (*r)[1].is_number_integer())
        ex.first = (*r)[0].get<long>(), ex.last = (*r)[1].get<long>();
    }
  } else if (!frames.empty()) {
    problem = "holds " + std::to_string(frames.size()) + " frame_*.png file(s) but no manifest.json";
  }
  if (problem.empty()) return ex;
  if (!force)
    throw InputError("tumble: output folder " + dir.string() + " " + problem +
                     ".\ntumble: choose another folder with -o, or add --force to replace that render");
  // --force: the old render goes, so none of its frames can pass for ours later
  // (a resumed run trusts every frame file in the folder).
  std::cerr << "tumble: --force: removing the previous render in " << dir.string() << " (" << frames.size()
            << " frames)\n";
  for (const fs::path& f : frames) remove_file(f);
  if (old_video && !old_video->empty() && fs::path(*old_video).filename() == *old_video &&
      *old_video != "manifest.json")
    remove_file(dir / *old_video);
  if (has_manifest) remove_file(mpath);
  return {};
}

std::string video_file_name(const scene::Scene& s, scene::VideoFormat f) {
  // The loader restricts names to [A-Za-z0-9_.-]; still, never leave the folder.
  std::string base = s.name;
  if (base.empty() || fs::path(base).filename() != base || base == "." || base == "..") base = "video";
  return base + (f == scene::VideoFormat::mp4 ? ".mp4" : ".gif");
}

}  // namespace tumble::app
