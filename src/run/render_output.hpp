// The output folder of `tumble render`: its manifest, its frame files, and
// what may be done with a folder that already holds a render.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace tumble::run {

/// manifest.json: what was rendered, how, and whether it finished.
struct Manifest {
  std::string scene_path, scene_name, scene_hash, settings_hash, method, step, gl_version, gl_renderer, backend;
  std::string gl_vendor, gl_device;  ///< GL_VENDOR; the display or EGL device ("EGL device 1 of 2 (/dev/dri/renderD129)")
  bool hardware_gpu = false;         ///< drawn by a GPU, not llvmpipe and the like
  std::string video_encoder;         ///< "libx264 ultrafast", "h264_nvenc p4"; empty without an mp4
  std::string video;        ///< file name in the folder; empty = none made ("video": null)
  std::string video_error;  ///< why a wanted video is missing (ffmpeg missing, failed, interrupted)
  std::string frames_out = "png";  ///< "png", or "none": frames streamed into the video only
  scene::FrameSettings frame;  ///< size, aa, video format, CRF (from the quality)
  double dt = 0, fps = 0;  // dt: the scene's; `step` says what each run really used
  int samples = 0;         ///< MSAA samples the renderer used (0 unless aa is msaa)
  long frame_count = 0, first = 0, last = -1, written = 0;
  bool complete = false;
  /// Replacing an earlier render of this scene (edited): until the last frame
  /// is written, the folder mixes its frames with ours, so --resume trusts none.
  bool replacing = false;

  std::string json() const;  ///< the file's text
};

/// Leftovers of a process killed mid-write: io::temp_path_for names of a
/// frame, the manifest or a video. Never a finished file.
bool is_stale_temp(const std::string& name);
/// Files of `dir` whose names pass `pred`, sorted; throws io::IoError.
std::vector<std::filesystem::path> list_dir(const std::filesystem::path& dir, bool (*pred)(const std::string&));
void remove_file(const std::filesystem::path& p);
/// Hash of everything that changes a frame's pixels (not the frame range:
/// --frames A:B writes the same bytes as a full run).
std::string settings_hash(const scene::Scene& s, const std::string& method);

/// What is already in the output folder, and what we may do with it.
struct Existing {
  bool resumable = false;       ///< a manifest of this scene with these settings
  long first = 0, last = -1;    ///< its frame range
  /// An earlier render of the same scene file (same path or name), edited or
  /// with other settings: its frames are overwritten one by one (each
  /// atomically) and the rest removed once ours exist (remove_stale).
  bool replacing = false;
  std::string old_video;        ///< its video file name, if any
};
/// Reads manifest.json and every manifest part in `dir`; `own` is the one this
/// run writes (manifest.json, or its part), the only one --resume continues.
/// Refuses (InputError) to write over another scene's render unless `force`;
/// with `force`, removes that render's frames, videos and manifests first.
Existing inspect_output(const std::filesystem::path& dir, const Manifest& want, const std::string& own, bool force);
/// After a replacing render wrote frames first..last: removes the earlier
/// render's other frames (not those of parts with `settings_hash`: shards
/// running beside us), its parts, its video (unless it is `keep_video`) and,
/// when `own` is a part, its manifest.json.
void remove_stale(const std::filesystem::path& dir, const Existing& ex, const std::string& settings_hash,
                  const std::string& own, long first, long last, const std::string& keep_video);
/// "<scene name>.mp4" / ".gif", never a path out of the folder.
std::string video_file_name(const std::string& scene_name, scene::VideoFormat f);
std::string video_file_name(const scene::Scene& s, scene::VideoFormat f);

}  // namespace tumble::run
