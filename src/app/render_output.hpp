// The output folder of `tumble render`: its manifest, its frame files, and
// what may be done with a folder that already holds a render.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace tumble::app {

/// manifest.json: what was rendered, how, and whether it finished.
struct Manifest {
  std::string scene_path, scene_hash, settings_hash, method, step, gl_version, gl_renderer, backend, video;
  double dt = 0, fps = 0;  // dt: the scene's; `step` says what each run really used
  int width = 0, height = 0, msaa = 0;
  long frame_count = 0, first = 0, last = -1, written = 0;
  bool complete = false;

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
};
/// Refuses (InputError) to write over another render unless `force`; with
/// `force`, removes that render's frames, video and manifest first.
Existing inspect_output(const std::filesystem::path& dir, const Manifest& want, bool force);
/// "<scene name>.mp4" / ".gif", never a path out of the folder.
std::string video_file_name(const scene::Scene& s, scene::VideoFormat f);

}  // namespace tumble::app
