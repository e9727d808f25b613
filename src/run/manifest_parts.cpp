#include "run/manifest_parts.hpp"

#include <algorithm>
#include <cstdio>

#include "run/render_output.hpp"
#include "scene/scene.hpp"

namespace tumble::run {

std::string part_manifest_name(long first, long last) {
  char name[64];
  std::snprintf(name, sizeof name, "manifest.part-%06ld-%06ld.json", first, last);
  return name;
}

bool is_part_manifest(const std::string& name) {
  long a = 0, b = 0;
  int used = 0;
  return name.rfind("manifest.part-", 0) == 0 &&
         std::sscanf(name.c_str(), "manifest.part-%6ld-%6ld.json%n", &a, &b, &used) == 2 &&
         used == static_cast<int>(name.size()) && name == part_manifest_name(a, b);
}

Part read_part(const std::filesystem::path& path) {
  Part p;
  p.file = path.filename().string();
  const std::optional<io::Json> j = io::read_json_file(path);
  if (!j || !j->is_object() || j->value("tool", "") != "tumble") return p;
  const char* field = "";
  try {
    auto get = [&](const char* name) -> const io::Json& { return j->at(field = name); };
    p.scene_hash = get("scene_hash").get<std::string>();
    p.settings_hash = get("settings_hash").get<std::string>();
    p.video_format = j->value(field = "video_format", "none");
    p.crf = j->value(field = "crf", 18);
    p.first = get("frames").at(0).get<long>();
    p.last = get("frames").at(1).get<long>();
    p.frame_count = get("frame_count").get<long>();
    p.written = get("frames_written").get<long>();
    p.complete = get("complete").get<bool>();
    p.width = get("width").get<int>();
    p.height = get("height").get<int>();
    p.fps = get("fps").get<double>();
  } catch (const io::Json::exception&) {
    p.bad_field = std::string(field) + " missing or of the wrong type";
    return p;  // not ok
  }
  // Numbers a disk or a hand could have changed stay within what a render
  // writes (frames 0 … ⌊duration·fps⌋ under the scene's cap), so nothing sized
  // by them (assemble's table of frames) can be absurd. The settings hash
  // does not cover the video's fields, so they are checked as the scene
  // checks them (and against the other parts, by assemble).
  const long cap = static_cast<long>(scene::kMaxFrames) + 1;
  if (p.frame_count < 1 || p.frame_count > cap || p.first < 0 || p.first > p.last || p.last >= p.frame_count ||
      p.written < 0 || p.written > p.last - p.first + 1)
    p.bad_field = "frames, frame_count or frames_written out of range";
  else if (!scene::parse_video_format(p.video_format))
    p.bad_field = "video_format '" + p.video_format + "' is not " + scene::video_format_choices();
  else if (p.crf < 0 || p.crf > 51)
    p.bad_field = "crf " + std::to_string(p.crf) + " is not in 0..51";
  else if (!(p.fps >= 1e-3 && p.fps <= 1000))
    p.bad_field = "fps is not in [0.001, 1000]";
  else if (p.width < scene::kMinFramePx || p.width > scene::kMaxFramePx || p.height < scene::kMinFramePx ||
           p.height > scene::kMaxFramePx)
    p.bad_field = "width or height is not in " + std::to_string(scene::kMinFramePx) + ".." +
                  std::to_string(scene::kMaxFramePx);
  if (!p.bad_field.empty()) return p;  // not ok
  p.json = *j;
  p.ok = true;
  return p;
}

std::vector<Part> read_parts(const std::filesystem::path& dir) {
  std::vector<Part> parts;
  for (const std::filesystem::path& f : list_dir(dir, is_part_manifest)) parts.push_back(read_part(f));
  return parts;
}

std::string missing_ranges(std::vector<std::pair<long, long>> covered, long count) {
  std::sort(covered.begin(), covered.end());
  std::string out;
  long next = 0;  // first frame not yet known to be covered
  auto gap = [&](long a, long b) {
    if (a <= b) out += (out.empty() ? "" : ", ") + std::to_string(a) + ":" + std::to_string(b);
  };
  for (const auto& [a, b] : covered) {
    gap(next, std::min(a, count) - 1);
    next = std::max(next, b + 1);
  }
  gap(next, count - 1);
  return out;
}

}  // namespace tumble::run
