#include "run/frame_range.hpp"

#include <string>

#include "base/error.hpp"

namespace tumble::run {

std::pair<long, long> parse_frame_range(const std::string& spec, long count) {
  const auto colon = spec.find(':');
  if (colon == std::string::npos) throw InputError("--frames: expected A:B (inclusive frame numbers), found '" + spec + "'");
  auto num = [&](const std::string& s, long dflt) -> long {
    if (s.empty()) return dflt;
    size_t used = 0;
    long v = -1;
    try {
      v = std::stol(s, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != s.size() || v < 0) throw InputError("--frames: expected a frame number >= 0, found '" + s + "'");
    return v;
  };
  const long a = num(spec.substr(0, colon), 0), b = num(spec.substr(colon + 1), count - 1);
  if (a > b)
    throw InputError("--frames " + spec + ": the first frame (" + std::to_string(a) + ") is after the last (" +
                     std::to_string(b) + "); expected A <= B");
  if (b >= count)
    throw InputError("--frames " + spec + ": the scene has frames 0:" + std::to_string(count - 1));
  return {a, b};
}

}  // namespace tumble::run
