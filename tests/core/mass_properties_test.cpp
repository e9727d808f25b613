#include <gtest/gtest.h>

#include "core/error.hpp"
#include "core/mass_properties.hpp"
#include "reference_problem.hpp"

namespace tumble {
namespace {

TEST(MassProperties, ReferenceCloudHasMoments123) {
  const MassProperties mp = compute_mass_properties(testing::reference_cloud(), "ref");
  EXPECT_DOUBLE_EQ(mp.mass, 3.0);
  EXPECT_NEAR(mp.principal_moments[0], 1.0, 1e-15);
  EXPECT_NEAR(mp.principal_moments[1], 2.0, 1e-15);
  EXPECT_NEAR(mp.principal_moments[2], 3.0, 1e-15);
  EXPECT_NEAR(mp.principal_axes.determinant(), 1.0, 1e-15);
}

}  // namespace
}  // namespace tumble
