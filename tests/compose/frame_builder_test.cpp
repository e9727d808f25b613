// The frame builder's text: the overlay line keeps clear of the view title and the name labels.
#include <filesystem>

#include <gtest/gtest.h>

#include "compose/frame_builder.hpp"
#include "scene/frame_runs.hpp"
#include "scene/scene.hpp"
#include "viz/draw_list.hpp"
#include "viz/text_layout.hpp"

namespace {

TEST(ViewText, OverlayClearsTheViewTitleAndTheNameLabels) {
  const tumble::scene::Scene s = tumble::scene::load_scene(std::filesystem::path(TUMBLE_SOURCE_DIR) / "scenes/poinsot.toml");
  const double fps = s.render.output.fps;
  const long k = 420;
  const auto runs = tumble::scene::simulate_runs(s, k + 1, fps);
  const tumble::compose::FrameBuilder fb(s, runs, fps, 320, 240);
  const tumble::viz::DrawList dl = fb.build(k);
  int overlays = 0;
  for (const tumble::viz::View& v : dl.views) {
    for (const tumble::viz::TextItem& o : v.texts) {
      if (o.text.rfind("t =", 0) != 0) continue;
      ++overlays;
      // No other text (the view's title, name labels, the key beside it) on its box.
      const tumble::viz::Box ob = tumble::viz::text_box(o);
      for (const tumble::viz::TextItem& t : v.texts) {
        if (&t == &o) continue;
        EXPECT_FALSE(tumble::viz::text_box(t).overlaps(ob)) << "'" << t.text << "' on '" << o.text << "'";
      }
    }
  }
  EXPECT_EQ(overlays, 2);  // the two world views (the poinsot views have none)
}

}  // namespace
