// The particle pass draws only the shell of a solid lattice; mesh surfaces become flat-shaded soups.
#include <gtest/gtest.h>

#include "viz/body_look.hpp"

namespace tumble::viz {
namespace {

TEST(BodyLook, SolidLatticeKeepsOnlyItsShell) {
  const ParticleCloud box = make_box({1.0, 0.5, 0.4}, {40, 20, 16}, 1.0);  // 12800 particles
  const auto visible = visible_particles(box);
  // The outer layer is 12800 - 38·18·14 = 3224 particles; a shell at most two deep.
  EXPECT_GE(visible.size(), 3224u);
  EXPECT_LT(visible.size(), 12800u - 36u * 16 * 12);
  // Every outer-layer particle is kept.
  std::vector<bool> kept(box.size(), false);
  for (auto i : visible) kept[i] = true;
  for (std::size_t i = 0; i < box.size(); ++i) {
    const Eigen::Vector3d p = box[i].position.cwiseAbs();
    if (p.x() > 0.48 || p.y() > 0.23 || p.z() > 0.18) {
      EXPECT_TRUE(kept[i]) << i;
    }
  }
  // A sparse cloud hides nothing.
  EXPECT_EQ(visible_particles(make_box({1, 1, 1}, {3, 3, 3}, 1.0)).size(), 27u);
}

TEST(BodyLook, SurfaceHasFlatOutwardNormals) {
  TriangleMesh m{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}};
  const auto s = make_surface(m);
  ASSERT_EQ(s->positions.size(), 3u);
  for (const auto& n : s->normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
}

}  // namespace
}  // namespace tumble::viz
