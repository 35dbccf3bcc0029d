// space.cpp: what every space shares, uniform states through from_unit and the resolution check.
#include "amp/core/space.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/core/joint_space.hpp"
#include "amp/core/state.hpp"

namespace amp::core {
namespace {

// sample_uniform is from_unit of unit_dimension() uniform draws, in order.
TEST(Space, SampleUniformIsFromUnitOfTheRngsDraws) {
  for (const int n : {1, 2, kMaxDof}) {
    SCOPED_TRACE(n);
    const JointSpace space = make_rn_space(std::vector<double>(static_cast<std::size_t>(n), -1.0),
                                           std::vector<double>(static_cast<std::size_t>(n), 3.0));
    ASSERT_EQ(space.unit_dimension(), n);
    Rng a(5), b(5);
    State s, t;
    for (int k = 0; k < 3; ++k) {
      space.sample_uniform(a, s);
      std::vector<double> u(static_cast<std::size_t>(n));
      for (double& x : u) x = b.uniform01();
      space.from_unit(u.data(), t);
      EXPECT_EQ(s, t);
      EXPECT_TRUE(space.in_bounds(s));
      for (int i = 0; i < n; ++i) EXPECT_DOUBLE_EQ(s[i], -1.0 + 4.0 * u[static_cast<std::size_t>(i)]);
    }
  }
}

TEST(Space, ResolutionMustBePositiveAndFinite) {
  JointSpace space("rn", {{"x", JointKind::kLinear, 0, 10, 1.0}}, 0.25);
  EXPECT_DOUBLE_EQ(space.resolution(), 2.5);  // fraction x extent
  space.set_resolution(0.125);
  EXPECT_EQ(space.resolution(), 0.125);
  for (const double bad : {0.0, -0.5, std::nan(""), std::numeric_limits<double>::infinity()}) {
    try {
      space.set_resolution(bad);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const ParameterError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("resolution must be a positive number, got ", 0), 0u) << e.what();
    }
  }
  EXPECT_EQ(space.resolution(), 0.125);  // unchanged by the refused values
}

}  // namespace
}  // namespace amp::core
