// A body's default colour is no vector's or curve's colour
// (docs/colours.md): the demo's T-handle was L's orange. Each default (a scene
// of six bodies without `color`) stays apart from the axes, L, ω, Π and the
// polhode, herpolhode and separatrix (the greys of the other levels, the plane
// and the text are no hue a viewer reads as a meaning).
#include <gtest/gtest.h>

#include "scene/scene.hpp"
#include "viz/palette.hpp"

namespace {

TEST(BodyColour, DefaultsAreApartFromEveryMeaning) {
  std::string toml = "[simulation]\nduration = 1.0\n";
  for (int i = 0; i < 6; ++i)
    toml += "[[bodies]]\nname = \"b" + std::to_string(i) + "\"\nshape = { type = \"box\", size = [0.3, 0.2, 0.1] }\n";
  const tumble::scene::Scene s = tumble::scene::load_scene_from_string(toml, "defaults.toml");
  ASSERT_EQ(s.bodies.size(), 6u);
  for (const tumble::scene::Body& b : s.bodies)
    for (const tumble::viz::MeaningColor& m : tumble::viz::kPalette) {
      using tumble::viz::Meaning;
      if (m.meaning == Meaning::other_levels || m.meaning == Meaning::plane || m.meaning == Meaning::ellipsoid ||
          m.meaning == Meaning::ink)
        continue;
      const Eigen::Vector3d c(m.rgba.r, m.rgba.g, m.rgba.b);
      // 0.3 in RGB: the old default blue and the demo's orange were 0.21 from e₃'s blue and L's orange.
      EXPECT_GT((b.color - c).norm(), 0.3) << b.name << " is too close to " << m.name << " (" << m.colour << ")";
    }
}

}  // namespace
