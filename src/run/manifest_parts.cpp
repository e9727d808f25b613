#include "run/manifest_parts.hpp"

#include <algorithm>
#include <cstdio>

#include "run/render_output.hpp"

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
  try {
    p.scene_hash = j->at("scene_hash").get<std::string>();
    p.settings_hash = j->at("settings_hash").get<std::string>();
    p.video_format = j->value("video_format", "none");
    p.crf = j->value("crf", 18);
    p.first = j->at("frames").at(0).get<long>();
    p.last = j->at("frames").at(1).get<long>();
    p.frame_count = j->at("frame_count").get<long>();
    p.written = j->at("frames_written").get<long>();
    p.complete = j->at("complete").get<bool>();
  } catch (const io::Json::exception&) {
    return p;  // not ok: a field missing or of the wrong type
  }
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
