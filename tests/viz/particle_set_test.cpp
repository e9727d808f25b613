// Drawable particle sets: the shell's exposed directions, the back-face rule
// (checked against brute-force ray casting: it never drops a particle that can
// be seen), and the level-of-detail rule.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "viz/body_look.hpp"
#include "viz/particle_set.hpp"

namespace tumble::viz {
namespace {

std::vector<glm::dvec3> positions(const ParticleCloud& c) {
  std::vector<glm::dvec3> out;
  for (const Particle& p : c) out.emplace_back(p.position.x(), p.position.y(), p.position.z());
  return out;
}

TEST(ParticleSet, BoxFaceParticlesAreExposedAlongTheirFaceOnly) {
  const ParticleCloud box = make_box({1.0, 0.5, 0.4}, {20, 10, 8}, 1.0);  // spacing 0.05
  const auto ps = positions(box);
  const auto exposed = exposed_directions(ps, shell_grid(ps));
  int interior = 0;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    const glm::dvec3 p = ps[i];
    const bool outer = std::abs(p.x) > 0.47 || std::abs(p.y) > 0.22 || std::abs(p.z) > 0.17;
    if (!outer) {
      EXPECT_EQ(exposed[i], 0) << i;
      ++interior;
    }
    // Middle of the +x face, two cells or more from its edges: +x alone.
    if (p.x > 0.47 && std::abs(p.y) < 0.13 && std::abs(p.z) < 0.08) {
      EXPECT_EQ(exposed[i], 1) << i;
    }
    if (p.z < -0.17 && std::abs(p.x) < 0.38 && std::abs(p.y) < 0.13) {
      EXPECT_EQ(exposed[i], 32) << i;
    }
  }
  EXPECT_EQ(interior, 18 * 8 * 6);
}

TEST(ParticleSet, FacesEyeRule) {
  const glm::vec3 p(1, 0, 0);
  EXPECT_TRUE(faces_eye(1, p, {5, 0, 0}, 0.1f));       // +x face seen from +x
  EXPECT_FALSE(faces_eye(1, p, {-5, 0, 0}, 0.1f));     // ... not from -x
  EXPECT_TRUE(faces_eye(1, p, {0.95f, 9, 0}, 0.1f));   // grazing, less than r behind its plane
  EXPECT_FALSE(faces_eye(1, p, {0.85f, 9, 0}, 0.1f));
  EXPECT_TRUE(faces_eye(1 | 4, p, {-5, 5, 0}, 0.1f));  // an edge particle: seen through +y
  EXPECT_TRUE(faces_eye(kAllDirections, p, {1, 0, 0}, 0.1f));
  EXPECT_FALSE(faces_eye(0, p, {5, 0, 0}, 0.1f));      // interior: never
}

// Is any point of sphere i visible from `eye` past all the other spheres?
bool sphere_visible(const std::vector<glm::dvec3>& c, double r, std::size_t i, const glm::dvec3& eye) {
  constexpr int kSamples = 96;  // Fibonacci points on the sphere
  for (int k = 0; k < kSamples; ++k) {
    const double z = 1 - 2 * (k + 0.5) / kSamples, phi = k * std::numbers::pi * (3 - std::sqrt(5.0));
    const glm::dvec3 n(std::sqrt(1 - z * z) * std::cos(phi), std::sqrt(1 - z * z) * std::sin(phi), z);
    const glm::dvec3 x = c[i] + 0.999 * r * n;
    if (glm::dot(n, eye - x) <= 0) continue;
    const glm::dvec3 d = glm::normalize(x - eye);
    const double tx = glm::length(x - eye);
    bool blocked = false;
    for (std::size_t j = 0; j < c.size() && !blocked; ++j) {
      if (j == i) continue;
      const glm::dvec3 o = eye - c[j];
      const double b = glm::dot(o, d), disc = b * b - (glm::dot(o, o) - r * r);
      blocked = disc > 0 && -b - std::sqrt(disc) < tx && -b + std::sqrt(disc) > 0;
    }
    if (!blocked) return true;
  }
  return false;
}

// Every particle of the cloud that brute-force ray casting can see is drawn:
// it is in level 0 and passes faces_eye. Spheres 0.75 spacing wide close
// the gaps between neighbours (gaps need r < spacing / √2).
void expect_conservative(const ParticleCloud& cloud, double spacing) {
  const auto ps = positions(cloud);
  const double r = 0.75 * spacing;
  const auto set = make_particle_set(cloud, std::vector<Color>(cloud.size(), Color(1)), float(r));
  const ParticleLevel& l0 = set->levels.at(0);
  const glm::dvec3 eyes[] = {{3, 0.2, 0.1}, {-2, 2, 1.5}, {0.4, -0.3, -3}, {1.7, 1.9, 2.1}, {-0.2, -2.5, 0.6}};
  std::size_t seen = 0;
  for (const glm::dvec3& eye : eyes) {
    Camera cam;
    cam.position = eye;
    std::vector<std::uint32_t> drawn;
    facing_particles(l0, glm::dmat4(1), cam, drawn);
    std::vector<bool> is_drawn(ps.size(), false);
    for (std::uint32_t k : drawn)
      for (std::size_t i = 0; i < ps.size(); ++i)  // level 0 keeps the cloud's positions
        if (glm::length(glm::dvec3(l0.positions[k]) - ps[i]) < 1e-6) is_drawn[i] = true;
    for (std::size_t i = 0; i < ps.size(); ++i)
      if (sphere_visible(ps, r, i, eye)) {
        ++seen;
        EXPECT_TRUE(is_drawn[i]) << "particle " << i << " is visible from (" << eye.x << ", " << eye.y << ", "
                                 << eye.z << ") but not drawn";
      }
  }
  EXPECT_GT(seen, 100u);
}

TEST(ParticleSet, BackFaceCullingNeverDropsAVisibleParticle) {
  expect_conservative(make_box({0.8, 0.6, 0.5}, {8, 6, 5}, 1.0), 0.1);
  // A staircase surface, whose normals lie between the grid axes.
  expect_conservative(make_ellipsoid({0.5, 0.4, 0.3}, 11, 1.0), 1.0 / 11);
}

TEST(ParticleSet, CullingDrawsAboutHalfTheShellOfABox) {
  const auto set = make_particle_set(make_box({0.6, 0.4, 0.2}, {100, 66, 30}, 1.0), {}, 0.0036f);
  for (const glm::dvec3 eye : {glm::dvec3{3, 0.2, 0.1}, {1.15, -1.7, 0.85}, {-2, 2, 1.5}}) {
    Camera cam;
    cam.position = eye;
    std::vector<std::uint32_t> drawn;
    facing_particles(set->levels[0], glm::dmat4(1), cam, drawn);
    // Three faces of six, and the rows along the edges of the other three.
    EXPECT_LT(drawn.size(), 0.55 * set->levels[0].positions.size());
    EXPECT_GT(drawn.size(), 0.45 * set->levels[0].positions.size());
  }
}

TEST(ParticleSet, CoarserLevelsMergeCellsAndDoubleTheRadius) {
  ParticleCloud box = make_box({1.6, 0.8, 0.8}, {64, 32, 32}, 1.0);
  std::vector<Color> colors;
  for (const Particle& p : box) colors.push_back(p.position.x() < 0 ? Color(1, 0, 0, 1) : Color(0, 0, 1, 1));
  const auto set = make_particle_set(box, colors, 0.01f);
  ASSERT_GE(set->levels.size(), 3u);
  EXPECT_EQ(set->levels[0].positions.size(), visible_particles(box).size());
  for (std::size_t l = 1; l < set->levels.size(); ++l) {
    const ParticleLevel &fine = set->levels[l - 1], &coarse = set->levels[l];
    EXPECT_FLOAT_EQ(coarse.radius, 2 * fine.radius);
    // A shell of cells twice as wide: about a quarter as many.
    EXPECT_NEAR(double(coarse.positions.size()) / double(fine.positions.size()), 0.25, 0.06) << l;
    for (std::size_t i = 0; i < coarse.positions.size(); ++i) {
      EXPECT_LE(glm::abs(coarse.positions[i].x), 0.8f);  // means stay inside the body
      // Cells do not straddle x = 0 (the grid starts at the body's corner): pure colours.
      const Color want = coarse.positions[i].x < 0 ? Color(1, 0, 0, 1) : Color(0, 0, 1, 1);
      EXPECT_EQ(coarse.colors[i], want) << l << " " << i;
    }
  }
}

TEST(ParticleSet, LevelOfDetailKeepsSpheresAtLeastOneAndAHalfPixels) {
  const auto set = make_particle_set(make_box({0.6, 0.4, 0.2}, {60, 40, 20}, 1.0), {}, 0.004f);
  ASSERT_GE(set->levels.size(), 3u);
  Camera cam;
  cam.fov_y_deg = 35;
  cam.target = {0, 0, 0};
  const double f = 360 / std::tan(glm::radians(17.5));  // px per m at unit depth, 720 px high
  auto at_depth = [&](double depth) {  // depth of the body's nearest point
    cam.position = {0, -(depth + set->bound_radius), 0};
    return particle_level(*set, glm::dmat4(1), cam, 720);
  };
  EXPECT_EQ(at_depth(0.004 * f / 3.0), 0u);  // 3 px: the finest
  EXPECT_EQ(at_depth(0.004 * f / 1.6), 0u);
  EXPECT_EQ(at_depth(0.004 * f / 1.4), 1u);  // 1.4 px -> 2.8 px at level 1
  EXPECT_EQ(at_depth(0.004 * f / 0.5), 2u);  // 0.5 -> 1 -> 2 px
  EXPECT_EQ(at_depth(1e6), set->levels.size() - 1);
  cam.position = {0, 0, 0};  // inside the body
  EXPECT_EQ(particle_level(*set, glm::dmat4(1), cam, 720), 0u);
}

}  // namespace
}  // namespace tumble::viz
