// `tumble assemble DIR`: the shards of a render (`tumble render --frames A:B`,
// each with its manifest part) checked to add up, then one manifest.json and
// the video, as a single run would have made them.
#include <memory>
#include <optional>

#include "app/commands.hpp"
#include "app/progress.hpp"
#include "base/error.hpp"
#include "run/assemble.hpp"

namespace tumble::app {

namespace {

struct AssembleOptions {
  std::string dir, video, progress = "auto";
};

int run_assemble(const AssembleOptions& o) {
  if (o.progress != "auto" && o.progress != "none")
    throw InputError("--progress: expected auto or none, found '" + o.progress + "'");
  const std::optional<scene::VideoFormat> video = scene::parse_video_format(o.video);
  if (!o.video.empty() && !video)
    throw InputError("--video: expected " + scene::video_format_choices() + ", found '" + o.video + "'");
  ConsoleListener listener(o.progress != "none");
  return exit_code(run::assemble(o.dir, video, listener));
}

}  // namespace

void add_assemble_command(CLI::App& app, Action& action) {
  const auto [cmd, o] = add_command(app, action, "assemble",
                                    "Check that the shards of a render (tumble render --frames A:B) cover every "
                                    "frame, then write manifest.json and the video", run_assemble);
  cmd->add_option("dir", o->dir, "The output folder the shards rendered into")->required()->check(kPath);
  cmd->add_option("--video", o->video, scene::video_format_choices() + " (default: the video the shards were rendered for)");
  cmd->add_option("--progress", o->progress, "auto (a bar on a terminal) or none");
}

}  // namespace tumble::app
