#include "app/render_output.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

#include "app/atomic_file.hpp"
#include "app/commands.hpp"
#include "core/error.hpp"

namespace tumble::app {

namespace fs = std::filesystem;

namespace {
std::string quoted_or_null(const std::string& v) { return v.empty() ? "null" : "\"" + json_escape(v) + "\""; }
}  // namespace

std::string Manifest::json() const {
  std::ostringstream o;
  o << "{\n  \"tool\": \"tumble\",\n  \"version\": \"" << TUMBLE_VERSION << "\",\n"
    << "  \"scene\": \"" << json_escape(scene_path) << "\",\n  \"scene_name\": \"" << json_escape(scene_name)
    << "\",\n  \"scene_hash\": \"" << scene_hash << "\",\n"
    << "  \"settings_hash\": \"" << settings_hash << "\",\n"
    << "  \"method\": \"" << json_escape(method) << "\",\n  \"step\": \"" << json_escape(step) << "\",\n"
    << "  \"dt\": " << format_double(dt) << ",\n"
    << "  \"fps\": " << format_double(fps) << ",\n  \"width\": " << width << ",\n  \"height\": " << height
    << ",\n  \"msaa\": " << msaa << ",\n  \"frame_count\": " << frame_count << ",\n  \"frames\": [" << first
    << ", " << last << "],\n  \"frames_written\": " << written << ",\n  \"gl_backend\": \"" << backend
    << "\",\n  \"gl_version\": \"" << json_escape(gl_version) << "\",\n  \"gl_renderer\": \""
    << json_escape(gl_renderer) << "\",\n  \"video\": " << quoted_or_null(video)
    << ",\n  \"video_error\": " << quoted_or_null(video_error) << ",\n  \"replacing\": " << (replacing ? "true" : "false") << ",\n  \"complete\": "
    << (complete ? "true" : "false") << "\n}\n";
  return o.str();
}

fs::path frame_path(const fs::path& dir, long k) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%06ld.png", k);
  return dir / name;
}

std::optional<std::string> manifest_field(const std::string& json, const std::string& key) {
  const std::string tag = "\"" + key + "\": ";
  const auto at = json.find(tag);
  if (at == std::string::npos) return std::nullopt;
  const auto start = at + tag.size();
  const auto end = json.find_first_of(",\n", start);
  std::string v = json.substr(start, end == std::string::npos ? std::string::npos : end - start);
  if (v.size() >= 2 && v.front() == '"' && v.back() == '"') v = v.substr(1, v.size() - 2);
  return v;
}

namespace {
bool is_video_name(const std::string& name) {
  const auto ends = [&](const char* ext) {
    const std::string e(ext);
    return name.size() > e.size() && name.compare(name.size() - e.size(), e.size(), e) == 0;
  };
  return ends(".mp4") || ends(".gif");
}
}  // namespace

bool is_frame_file(const std::string& name) {
  return name.size() == 16 && name.rfind("frame_", 0) == 0 && name.compare(12, 4, ".png") == 0 &&
         std::all_of(name.begin() + 6, name.begin() + 12, [](char c) { return c >= '0' && c <= '9'; });
}

bool is_stale_temp(const std::string& name) {
  return (name.rfind("frame_", 0) == 0 || name.rfind("manifest.json", 0) == 0 ||
          name.find(".tmp.mp4") != std::string::npos || name.find(".tmp.gif") != std::string::npos) &&
         (name.find(".tmp.") != std::string::npos || name.find(".tmp-") != std::string::npos);
}

std::vector<fs::path> list_dir(const fs::path& dir, bool (*pred)(const std::string&)) {
  std::vector<fs::path> out;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (pred(it->path().filename().string())) out.push_back(it->path());
  if (ec) throw IoError("cannot list output folder '" + dir.string() + "': " + ec.message());
  std::sort(out.begin(), out.end());
  return out;
}

void remove_file(const fs::path& p) {
  std::error_code ec;
  fs::remove(p, ec);
  if (ec) throw IoError("cannot remove '" + p.string() + "': " + ec.message());
}

std::string settings_hash(const scene::Scene& s, const std::string& method) {
  const scene::OutputConfig& out = s.render.output;
  std::ostringstream k;
  k << s.content_hash << '|' << method << '|' << format_double(s.simulation.dt) << '|' << format_double(out.fps)
    << '|' << out.width << 'x' << out.height << '|' << out.msaa;
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

}  // namespace

Existing inspect_output(const fs::path& dir, const Manifest& want, bool force) {
  Existing ex;
  const fs::path mpath = dir / "manifest.json";
  std::error_code ec;
  const bool has_manifest = fs::exists(mpath, ec);
  const std::vector<fs::path> frames = list_dir(dir, is_frame_file);
  std::string problem;
  std::optional<std::string> old_video;
  if (has_manifest) {
    std::ifstream in(mpath, std::ios::binary);
    std::stringstream buf;
    buf << in.rdbuf();
    const std::string m = buf.str();
    const auto hash = manifest_field(m, "scene_hash"), settings = manifest_field(m, "settings_hash");
    old_video = manifest_field(m, "video");
    const bool same_file = same_scene_file(manifest_field(m, "scene"), manifest_field(m, "scene_name"), want);
    if (!in || manifest_field(m, "tool") != std::optional<std::string>("tumble") || !hash) {
      problem = "holds a manifest.json that tumble did not write";
    } else if (*hash != want.scene_hash && !same_file) {
      problem = "holds a render of another scene (" + manifest_field(m, "scene").value_or("?") + ", hash " + *hash +
                "; this scene's hash is " + want.scene_hash + ")";
    } else if (*hash != want.scene_hash || settings != want.settings_hash ||
               manifest_field(m, "replacing") == std::optional<std::string>("true")) {
      // The edit loop: the same scene file, changed (or other settings, or a
      // replacement that was interrupted). Its frames are replaced, not trusted.
      ex.replacing = true;
      if (old_video && *old_video != "null") ex.old_video = *old_video;
      return ex;
    } else {
      ex.resumable = true;
      if (auto r = manifest_field(m, "frames")) {  // "[A, B]"
        long a = 0, b = -1;
        if (std::sscanf(r->c_str(), "[%ld", &a) == 1) {
          const auto comma = m.find(", ", m.find("\"frames\": ["));
          if (comma != std::string::npos && std::sscanf(m.c_str() + comma + 2, "%ld", &b) == 1) ex.first = a, ex.last = b;
        }
      }
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
  if (old_video && !old_video->empty() && *old_video != "null" && fs::path(*old_video).filename() == *old_video &&
      *old_video != "manifest.json")
    remove_file(dir / *old_video);
  if (has_manifest) remove_file(mpath);
  return {};
}

void remove_stale(const fs::path& dir, const Existing& ex, long first, long last, const std::string& keep_video) {
  if (!ex.replacing) return;
  for (const fs::path& f : list_dir(dir, is_frame_file)) {
    const long k = std::atol(f.filename().string().c_str() + 6);
    if (k < first || k > last) remove_file(f);
  }
  if (!ex.old_video.empty() && ex.old_video != keep_video && fs::path(ex.old_video).filename() == ex.old_video &&
      ex.old_video != "manifest.json" && is_video_name(ex.old_video))
    remove_file(dir / ex.old_video);
}

std::string video_file_name(const scene::Scene& s, scene::VideoFormat f) {
  // The loader restricts names to [A-Za-z0-9_.-]; still, never leave the folder.
  std::string base = s.name;
  if (base.empty() || fs::path(base).filename() != base || base == "." || base == "..") base = "video";
  return base + (f == scene::VideoFormat::mp4 ? ".mp4" : ".gif");
}

}  // namespace tumble::app
