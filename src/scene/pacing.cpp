// Pacing checks of an explanatory video at load: a caption must stay up long
// enough to be read aloud in a lecture hall, and two captions must not share
// one place at one time.
#include <algorithm>
#include <cstdio>
#include <sstream>

#include "scene/frame_clock.hpp"
#include "scene/internal.hpp"

namespace tumble::scene::detail {

namespace {

std::size_t word_count(const std::string& text) {
  std::istringstream in(text);
  std::size_t n = 0;
  for (std::string w; in >> w;) ++n;
  return n;
}

std::string seconds(double s, int digits = 1) {
  char b[32];
  std::snprintf(b, sizeof b, "%.*f s", digits, s);
  return b;
}

}  // namespace

void check_pacing(TableReader& root, LoadContext& ctx, const Scene& scene) {
  const auto& captions = scene.render.explain.captions;
  const auto tables = root.tables("captions");
  if (captions.size() != tables.size()) return;  // a broken table: its error says so
  const FrameClock clock = frame_clock(scene, scene.render.output.fps);
  auto where = [&](std::size_t i, const char* key) {
    const toml::node* n = tables[i]->get(key);
    return n ? n->source() : tables[i]->source();
  };
  for (std::size_t i = 0; i < captions.size(); ++i) {
    const Caption& c = captions[i];
    const auto [a, b] = caption_video_span(clock, c);
    const std::size_t words = word_count(c.text);
    const std::string from = c.start_text.empty() ? format_number(c.start) : c.start_text;
    const std::string to = c.end_text.empty() ? format_number(c.end) : c.end_text;
    const std::string when = c.seconds > 0 ? "from " + seconds(c.after) + " of video after simulated " + from
                                           : from + " to " + to + " simulated s";
    const double need = kSecondsPerWord * static_cast<double>(words);
    if (b - a < need)
      ctx.diag.warning(where(i, "text"), "captions[" + std::to_string(i) + "].text",
                       "up for " + seconds(b - a, 2) + " of video (" + when + ") for " +
                           std::to_string(words) + " words; a hall reads about " + seconds(kSecondsPerWord) +
                           " a word, so it needs " + seconds(need) +
                           ": move its end (or seconds), slow the time down over it ([[slow_motion]], [[holds]]) or shorten it");
    for (std::size_t j = 0; j < i; ++j) {
      const Caption& o = captions[j];
      const auto [oa, ob] = caption_video_span(clock, o);
      if (a < ob && oa < b)
        ctx.diag.warning(where(i, "start"), "captions[" + std::to_string(i) + "].start",
                         "shown at the same time as captions[" + std::to_string(j) + "] (video " +
                             seconds(std::max(a, oa)) + " to " + seconds(std::min(b, ob)) +
                             ") in the one caption strip, so one hides the other; end the first before the second starts");
    }
  }
}

}  // namespace tumble::scene::detail
