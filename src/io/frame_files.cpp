#include "io/frame_files.hpp"

#include <algorithm>
#include <cstdio>

namespace tumble::io {

std::filesystem::path frame_path(const std::filesystem::path& dir, long k) {
  char name[32];
  std::snprintf(name, sizeof name, kFramePattern, static_cast<int>(k));
  return dir / name;
}

bool is_frame_file(const std::string& name) {
  return name.size() == 16 && name.rfind("frame_", 0) == 0 && name.compare(12, 4, ".png") == 0 &&
         std::all_of(name.begin() + 6, name.begin() + 12, [](char c) { return c >= '0' && c <= '9'; });
}

std::optional<long> frame_index(const std::string& name) {
  if (!is_frame_file(name)) return std::nullopt;
  long k = 0;
  for (auto c = name.begin() + 6; c != name.begin() + 12; ++c) k = 10 * k + (*c - '0');
  return k;
}

}  // namespace tumble::io
