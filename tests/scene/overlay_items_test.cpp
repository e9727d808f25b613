// A world view's own readout (`readout`, of its body) and `until`, and the
// overlay's axis angles: read from one list of item names; each bad value an
// error at its file:line:col.
#include <gtest/gtest.h>

#include "scene/scene.hpp"
#include "scene_error.hpp"

namespace tumble::scene {
namespace {

const char* kTwo = R"(name = "two"
[simulation]
method = "exact"
duration = 4.0
fps = 30
[[bodies]]
name = "a"
shape = { type = "t_handle", handle_length = 0.8, stem_length = 0.4, thickness = 0.1, resolution = 20, mass = 1.0 }
omega_body = [0.25, 4.0, 0.7]
[[bodies]]
name = "b"
shape = { type = "t_handle", handle_length = 0.8, stem_length = 0.4, thickness = 0.1, resolution = 20, mass = 1.0 }
position = [4.0, 0.0, 0.0]
omega_body = [4.0, 0.5, 0.0]
[[views]]
kind = "world"
body = "a"
until = 2.0
)";

Scene load(const std::string& extra) { return load_scene_from_string(kTwo + extra, "two.toml"); }
std::string error_of(const std::string& extra) { return scene_error(kTwo + extra, "two.toml"); }

TEST(ViewReadout, AViewOfOneBodyReadsItsItemsAndUntil) {
  const Scene s = load("[[views]]\nkind = \"world\"\nbody = \"b\"\nappear = 2.0\nreadout = [\"angle\", \"e1_angle\"]\n");
  ASSERT_EQ(s.render.explain.views.size(), 2u);
  const ViewConfig& first = s.render.explain.views[0];
  EXPECT_FALSE(first.readout.has_value());
  EXPECT_DOUBLE_EQ(first.until, 2.0);
  const ViewConfig& second = s.render.explain.views[1];
  EXPECT_GT(second.until, 1e299);  // none: drawn to the end
  ASSERT_TRUE(second.readout.has_value());
  EXPECT_TRUE(second.readout->angle);
  EXPECT_TRUE(second.readout->e1_angle);
  EXPECT_FALSE(second.readout->e2_angle || second.readout->e3_angle || second.readout->time || second.readout->state);
}

TEST(ViewReadout, TheOverlayTakesTheAxisAngles) {
  const Scene s = load("[draw]\noverlay = [\"time\", \"e2_angle\"]\n");
  EXPECT_TRUE(s.render.draw.overlay);
  EXPECT_TRUE(s.render.draw.overlay_items.time && s.render.draw.overlay_items.e2_angle);
  EXPECT_FALSE(s.render.draw.overlay_items.angle || s.render.draw.overlay_items.e1_angle ||
               s.render.draw.overlay_items.energy || s.render.draw.overlay_items.method);
}

TEST(ViewReadout, BadReadoutsAndUntilsAreErrorsAtTheirPlace) {
  // Not a world view of one body.
  EXPECT_NE(error_of("[[views]]\nkind = \"world\"\nreadout = [\"angle\"]\n").find("two.toml:21:11: error: views[1].readout: only a world view of one body"),
            std::string::npos)
      << error_of("[[views]]\nkind = \"world\"\nreadout = [\"angle\"]\n");
  EXPECT_NE(error_of("[[views]]\nkind = \"plot\"\nreadout = [\"angle\"]\n").find("views[1].readout: only a world view"), std::string::npos);
  // The frame's items, or unknown ones.
  EXPECT_NE(error_of("[[views]]\nkind = \"world\"\nbody = \"b\"\nreadout = [\"energy\"]\n").find("method, step and energy are the frame's"),
            std::string::npos);
  EXPECT_NE(error_of("[[views]]\nkind = \"world\"\nbody = \"b\"\nreadout = [\"e4_angle\"]\n").find("found \"e4_angle\""), std::string::npos);
  EXPECT_NE(error_of("[[views]]\nkind = \"world\"\nbody = \"b\"\nreadout = \"angle\"\n").find("views[1].readout: expected a list"),
            std::string::npos);
  EXPECT_NE(error_of("[draw]\noverlay = [\"e2_angle\", \"axis\"]\n").find("overlay: expected items from"), std::string::npos);
  // Gone before it came.
  EXPECT_NE(error_of("[[views]]\nkind = \"world\"\nbody = \"b\"\nappear = 2.0\nuntil = 1.0\n").find("views[1].until: expected a time after"),
            std::string::npos);
  EXPECT_NE(error_of("[[views]]\nkind = \"world\"\nbody = \"b\"\nuntil = \"later\"\n").find("views[1].until"), std::string::npos);
}

}  // namespace
}  // namespace tumble::scene
