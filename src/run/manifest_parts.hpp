// Shards of a render: each `tumble render --frames A:B` run that is not the
// whole render writes manifest.part-<A>-<B>.json instead of manifest.json, so
// runs in parallel never overwrite each other's record; `tumble assemble`
// checks that the parts add up and writes the combined manifest.json.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "io/json.hpp"

namespace tumble::run {

/// "manifest.part-000120-000239.json" (six digits, like the frames, so they sort).
std::string part_manifest_name(long first, long last);
/// Whether `name` (no folder) is such a part.
bool is_part_manifest(const std::string& name);

/// One part as read back; `ok` false when it is not a manifest tumble wrote
/// (unreadable, a field missing, or frames out of range).
struct Part {
  std::string file;  ///< name in the folder
  bool ok = false, complete = false;
  std::string scene_hash, settings_hash, video_format;
  long first = 0, last = -1, frame_count = 0, written = 0;
  int crf = 0, width = 0, height = 0;
  double fps = 0;
  std::string bad_field;  ///< when !ok: the field missing, mistyped or out of range
  io::Json json;
};
Part read_part(const std::filesystem::path& path);
/// Every manifest.part-*.json in `dir`, sorted by name (first frame). Throws io::IoError.
std::vector<Part> read_parts(const std::filesystem::path& dir);

/// The frames of 0..count-1 that no range covers, as "A:B" ranges joined by
/// ", " (a single frame is "A:A"); empty when every frame is covered.
std::string missing_ranges(std::vector<std::pair<long, long>> covered, long count);

}  // namespace tumble::run
