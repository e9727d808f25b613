// What a pipeline of src/run tells its caller while it works, and how it
// ended. The pipeline never prints, installs signal handlers or exits: app
// shows the notes and progress, answers stop() from its signal handlers and
// maps an Outcome to an exit code.
#pragma once

#include <string>

namespace tumble::run {

class Listener {
 public:
  virtual ~Listener() = default;
  /// One line for the user (app writes "tumble: <line>" to stderr).
  virtual void note(const std::string& line) = 0;
  /// Counted work (frames drawn or encoded): `what`, when not empty, says what
  /// starts; shown only with the progress bar.
  virtual void begin(long total, const std::string& what = {}) = 0;
  virtual void advance(long done) = 0;
  virtual void end() = 0;
  /// From here on files change: a stop request (Ctrl-C, SIGTERM) must stop the
  /// work between frames instead of killing the process.
  virtual void arm_stop() = 0;
  /// The stop signal received since arm_stop (SIGINT, SIGTERM), 0 = none.
  virtual int stop() const = 0;
};

/// How a render or an assemble ended. Bad input and I/O errors are thrown
/// (InputError, io::IoError) before or instead of an Outcome.
struct Outcome {
  enum Kind { done, failed, diverged, interrupted } kind = done;
  int signal = 0;       ///< interrupted: SIGINT or SIGTERM
  std::string summary;  ///< done: what was made, one line for stdout
};

/// `a` quoted for a POSIX shell when it needs it: for "run it again with" hints.
std::string quote_arg(const std::string& a);

}  // namespace tumble::run

namespace tumble::compose {
class LayoutNotes;
}

namespace tumble::run {

/// The layout's notes (what was left out of which frames, and why), each a "warning: " note.
void warn_layout(const compose::LayoutNotes& notes, Listener& l);

}  // namespace tumble::run
