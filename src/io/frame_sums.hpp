// What a render wrote, so that nothing on disk is trusted unchecked: each frame,
// once renamed into place, appends "NAME SIZE HASH" to DIR/frames.sums (one
// O_APPEND write, so threads and concurrent shards never interleave). A frame
// survives a resume or an assemble only when it is a regular file (not a
// link), its size and FNV-1a hash match its last line, and it decodes whole
// at the render's size. A line, not the manifest: it is on disk the moment the
// frame is, so a kill -9 loses at most the lines of the frames in flight
// (which are then drawn again).
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>

namespace tumble::io {

inline constexpr const char* kFrameSumsName = "frames.sums";

struct FrameSum {
  std::uint64_t size = 0;
  std::string hash;  ///< FNV-1a 64 of the bytes, 16 hex digits
};

/// Appends `frame`'s size and hash (read back from disk) to its folder's
/// frames.sums. Throws IoError.
void record_frame(const std::filesystem::path& frame);

/// The last record of each frame name in DIR/frames.sums (none: empty);
/// a torn last line (a kill mid-write) is ignored.
std::map<std::string, FrameSum> read_frame_sums(const std::filesystem::path& dir);

/// "" when `frame` is whole and is what was recorded, else why not
/// ("not recorded", "a symbolic link", "12 bytes, recorded 4096", ...).
std::string check_frame(const std::filesystem::path& frame, const std::map<std::string, FrameSum>& sums, int width,
                        int height);

}  // namespace tumble::io
