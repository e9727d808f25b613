// What the layout left out over a video, said once per element: each note of
// the frames' draw lists (viz::DrawList::notes: a key that does not fit, a
// label with no free place) with the frames it held in, as ranges, for the
// warnings of `tumble render`, `storyboard` and `info`.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace tumble::scene {
struct Scene;
}

namespace tumble::compose {

class LayoutNotes {
 public:
  /// Frame k's notes (frames may come in any order; each once).
  void add(long frame, const std::vector<std::string>& notes);
  /// One line per note, in the order first seen: "<note> (frames 0-479)",
  /// "(frame 12)", "(frames 3-9, 20-31 and 4 more stretches)".
  std::vector<std::string> lines() const;
  bool empty() const { return entries_.empty(); }

 private:
  struct Entry {
    std::string note;
    std::vector<std::pair<long, long>> ranges;  // inclusive, in the order added
  };
  std::vector<Entry> entries_;
};

/// The notes of every frame of `s` at its [output] size, as `tumble render`
/// lays them out (simulated, composed, no pixels): what `tumble info` says.
LayoutNotes check_layout(const scene::Scene& s);

}  // namespace tumble::compose
