#include "amp/core/joint_space.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"

namespace amp::core {
namespace {

constexpr double kPi = std::numbers::pi;

State make(std::initializer_list<double> v) {
  State s(static_cast<int>(v.size()));
  int i = 0;
  for (double x : v) s[i++] = x;
  return s;
}

TEST(JointSpace, Se2DistanceGoesTheShortWayRoundTheAngle) {
  const JointSpace se2 = make_se2_space(0, 0, 10, 10, 2.0);
  // 3.1 and -3.1 are 0.083 rad apart across +-pi, not 6.2.
  const double d = se2.distance(make({1, 1, 3.1}), make({1, 1, -3.1}));
  EXPECT_NEAR(d, 2.0 * (2 * kPi - 6.2), 1e-12);
  EXPECT_NEAR(se2.distance(make({0, 0, 0}), make({3, 4, 0})), 5.0, 1e-12);
  // theta and theta + 2pi are the same state.
  EXPECT_NEAR(se2.distance(make({2, 2, 0.5}), make({2, 2, 0.5 + 2 * kPi})), 0.0, 1e-12);
}

TEST(JointSpace, InterpolationCrossesPiAndStaysWrapped) {
  const JointSpace se2 = make_se2_space(0, 0, 10, 10, 1.0);
  State mid;
  se2.interpolate(make({0, 0, 3.0}), make({2, 4, -3.0}), 0.5, mid);
  EXPECT_NEAR(mid[0], 1.0, 1e-12);
  EXPECT_NEAR(mid[1], 2.0, 1e-12);
  EXPECT_NEAR(std::abs(mid[2]), kPi, 1e-12);  // halfway across the seam
  se2.interpolate(make({0, 0, 3.0}), make({2, 4, -3.0}), 1.0, mid);
  EXPECT_NEAR(mid[2], -3.0, 1e-12);
}

TEST(JointSpace, RevoluteJointsDoNotWrap) {
  const JointSpace arm("linkage", {{"j0", JointKind::kRevolute, -3.0, 3.0, 1.0}});
  State mid;
  arm.interpolate(make({2.9}), make({-2.9}), 0.5, mid);
  EXPECT_NEAR(mid[0], 0.0, 1e-12);  // through zero, not through the joint stop
  EXPECT_NEAR(arm.distance(make({2.9}), make({-2.9})), 5.8, 1e-12);
  EXPECT_FALSE(arm.in_bounds(make({3.2})));
}

TEST(JointSpace, SamplesStayInBoundsAndAreSeedDeterministic) {
  const JointSpace s("linkage", {{"x", JointKind::kLinear, -1, 2, 1.0},
                                 {"a", JointKind::kContinuous, 0, 0, 1.0},
                                 {"b", JointKind::kRevolute, -1, 1, 1.0}});
  Rng a(7), b(7);
  for (int i = 0; i < 1000; ++i) {
    State x, y;
    s.sample_uniform(a, x);
    s.sample_uniform(b, y);
    ASSERT_TRUE(s.in_bounds(x));
    ASSERT_EQ(x, y);
  }
}

TEST(JointSpace, EmbeddingDistanceIsALowerBoundOfTheMetric) {
  const JointSpace s("linkage", {{"x", JointKind::kLinear, -1, 2, 0.5},
                                 {"a", JointKind::kContinuous, 0, 0, 2.0},
                                 {"b", JointKind::kRevolute, -1, 1, 1.0}});
  Rng rng(3);
  for (int i = 0; i < 2000; ++i) {
    State x, y;
    s.sample_uniform(rng, x);
    s.sample_uniform(rng, y);
    double ex[8], ey[8], sq = 0;
    s.embed(x, ex);
    s.embed(y, ey);
    for (int j = 0; j < s.embedding_dimension(); ++j) sq += (ex[j] - ey[j]) * (ex[j] - ey[j]);
    ASSERT_LE(std::sqrt(sq), s.distance(x, y) + 1e-12);
  }
}

TEST(JointSpace, RejectsNonsenseBoundsAndWeights) {
  EXPECT_THROW(JointSpace("rn", {{"x", JointKind::kLinear, 1, 1, 1}}), ParameterError);
  EXPECT_THROW(JointSpace("rn", {{"x", JointKind::kLinear, 0, 1, 0}}), ParameterError);
  EXPECT_THROW(JointSpace("linkage", {{"j", JointKind::kRevolute, -4, 4, 1}}), ParameterError);
  EXPECT_THROW(JointSpace("rn", {}), ParameterError);
  EXPECT_THROW(make_rn_space({0, 0}, {1, 1}).set_resolution(0.0), ParameterError);
}

TEST(JointSpace, WrapAngleMapsIntoHalfOpenRange) {
  EXPECT_NEAR(wrap_angle(3 * kPi), -kPi, 1e-12);
  EXPECT_NEAR(wrap_angle(-kPi), -kPi, 1e-12);
  EXPECT_NEAR(wrap_angle(0.25 + 4 * kPi), 0.25, 1e-12);
  EXPECT_NEAR(angle_difference(kPi - 0.1, -kPi + 0.1), 0.2, 1e-12);
}

}  // namespace
}  // namespace amp::core
