// The observables table: every column named once, every plotted component
// labelled, and each name found back to its row and component.
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "core/dynamics.hpp"
#include "core/observables.hpp"

namespace tumble {
namespace {

TEST(Observables, EveryColumnIsNamedOnceAndFoundBack) {
  std::set<std::string> seen;
  for (const Observable& o : observables()) {
    ASSERT_GE(o.size, 1u) << o.name;
    ASSERT_LE(o.size, kMaxComponents) << o.name;
    for (std::size_t i = 0; i < o.size; ++i) {
      EXPECT_TRUE(seen.insert(std::string(o.columns[i])).second) << o.columns[i] << " named twice";
      std::size_t k = 99;
      EXPECT_EQ(find_column(o.columns[i], &k), &o);
      EXPECT_EQ(k, i);
      if (o.use & kPlotSeries) EXPECT_FALSE(o.shown[i].empty()) << o.columns[i] << " is plotted with no key text";
    }
  }
  EXPECT_EQ(find_column("nope"), nullptr);
}

TEST(Observables, ValuesAreTheDynamicsFunctions) {
  RigidBodyModel m;
  m.mass = 2;
  m.inertia = {1, 2, 3};
  m.inv_inertia = {1, 0.5, 1.0 / 3.0};
  BodyState s;
  s.L = {0.3, 0.2, 0.1};
  s.P = {2, 0, 0};
  double v[kMaxComponents];
  std::size_t k = 0;
  find_column("wbx", &k)->value(m, s, 0, v);
  EXPECT_EQ(Eigen::Vector3d(v[0], v[1], v[2]), omega_body(m, s));
  find_column("energy_error")->value(m, s, 2 * total_energy(m, s), v);
  EXPECT_DOUBLE_EQ(v[0], -0.5);
  find_column("axis2_L")->value(m, s, 0, v);
  EXPECT_EQ(Eigen::Vector3d(v[0], v[1], v[2]), principal_axis_angles_to_L(s));
  find_column("vx")->value(m, s, 0, v);
  EXPECT_EQ(v[0], 1.0);
}

}  // namespace
}  // namespace tumble
