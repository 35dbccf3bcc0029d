// core/coordinate_layout.hpp: each space's Space::coordinate_layout(), and the metric the layout
// promises (KD-tree bounds and grid charts rely on it instead of the space's type).
#include "amp/core/coordinate_layout.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include <gtest/gtest.h>

#include "amp/core/joint_space.hpp"
#include "amp/core/rng.hpp"
#include "amp/core/se3_space.hpp"
#include "amp/core/unicycle_space.hpp"

namespace amp::core {
namespace {

constexpr double kPi = std::numbers::pi;

// The distance the layout's comment promises, computed from the layout alone.
double layout_distance(const CoordinateLayout& layout, const State& a, const State& b) {
  double sq = 0.0;
  for (std::size_t i = 0; i < layout.axes.size(); ++i) {
    const CoordinateAxis& axis = layout.axes[i];
    const auto e = static_cast<Eigen::Index>(i);
    const double d = axis.kind == CoordinateKind::kAngle ? angle_difference(a[e], b[e]) : b[e] - a[e];
    sq += (axis.weight * d) * (axis.weight * d);
  }
  double angle = 0.0;
  if (layout.quaternion) {
    const auto k = static_cast<Eigen::Index>(layout.axes.size());
    const double dot = std::abs(a.segment<4>(k).dot(b.segment<4>(k)));
    angle = 2.0 * std::acos(std::min(1.0, dot));
  }
  return std::sqrt(sq) + layout.rotation_weight * angle;
}

void expect_metric_matches(const Space& space, const CoordinateLayout& layout) {
  Rng rng(5);
  for (int i = 0; i < 500; ++i) {
    State a, b;
    space.sample_uniform(rng, a);
    space.sample_uniform(rng, b);
    const double d = space.distance(a, b);
    EXPECT_NEAR(layout_distance(layout, a, b), d, 1e-9 * (1.0 + d)) << space.kind();
  }
}

TEST(CoordinateLayout, JointSpacesListTheirJointsAsLinesAndAngles) {
  const JointSpace se2 = make_se2_space(-1, 0, 3, 2, 0.7);
  const std::optional<CoordinateLayout> layout = se2.coordinate_layout();
  ASSERT_TRUE(layout.has_value());
  ASSERT_EQ(layout->axes.size(), 3u);
  EXPECT_EQ(layout->axes[0].kind, CoordinateKind::kLinear);
  EXPECT_EQ(layout->axes[0].lo, -1.0);
  EXPECT_EQ(layout->axes[0].hi, 3.0);
  EXPECT_EQ(layout->axes[1].kind, CoordinateKind::kLinear);
  EXPECT_EQ(layout->axes[2].kind, CoordinateKind::kAngle);
  EXPECT_EQ(layout->axes[2].weight, 0.7);
  EXPECT_FALSE(layout->quaternion);
  EXPECT_FALSE(layout->rigid_body_3d());
  expect_metric_matches(se2, *layout);

  // A revolute joint has limits and never wraps: a line, as far as the layout goes.
  const JointSpace arm("linkage", {{"a", JointKind::kRevolute, -2, 2, 1.5}, {"b", JointKind::kContinuous, -kPi, kPi, 0.5}});
  const std::optional<CoordinateLayout> arm_layout = arm.coordinate_layout();
  ASSERT_TRUE(arm_layout.has_value());
  EXPECT_EQ(arm_layout->axes[0].kind, CoordinateKind::kLinear);
  EXPECT_EQ(arm_layout->axes[1].kind, CoordinateKind::kAngle);
  expect_metric_matches(arm, *arm_layout);
}

TEST(CoordinateLayout, Se3IsAPositionThenAQuaternion) {
  const Se3Space se3(Eigen::Vector3d(0, -1, 2), Eigen::Vector3d(4, 1, 3), 2.5, 0.8);
  const std::optional<CoordinateLayout> layout = se3.coordinate_layout();
  ASSERT_TRUE(layout.has_value());
  ASSERT_EQ(layout->axes.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    const CoordinateAxis& a = layout->axes[static_cast<std::size_t>(i)];
    EXPECT_EQ(a.kind, CoordinateKind::kLinear);
    EXPECT_EQ(a.lo, se3.lo()[i]);
    EXPECT_EQ(a.hi, se3.hi()[i]);
    EXPECT_EQ(a.weight, 0.8);
  }
  EXPECT_TRUE(layout->quaternion);
  EXPECT_EQ(layout->rotation_weight, 2.5);
  EXPECT_TRUE(layout->rigid_body_3d());
  expect_metric_matches(se3, *layout);
}

TEST(CoordinateLayout, ARigidBodyNeedsThreeEqualLinesBeforeItsQuaternion) {
  CoordinateLayout layout = *Se3Space(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1), 1.0).coordinate_layout();
  CoordinateLayout angle = layout;
  angle.axes[2].kind = CoordinateKind::kAngle;
  EXPECT_FALSE(angle.rigid_body_3d());
  CoordinateLayout uneven = layout;
  uneven.axes[1].weight = 2.0;
  EXPECT_FALSE(uneven.rigid_body_3d());
  CoordinateLayout planar = layout;
  planar.axes.pop_back();
  EXPECT_FALSE(planar.rigid_body_3d());
  layout.quaternion = false;
  EXPECT_FALSE(layout.rigid_body_3d());
}

TEST(CoordinateLayout, TheUnicycleOffersNone) {
  const UnicycleSpace unicycle({.x_min = 0, .x_max = 1, .y_min = 0, .y_max = 1, .v_min = 0, .v_max = 1,
                                .omega_min = -1, .omega_max = 1});
  EXPECT_FALSE(unicycle.coordinate_layout().has_value());
}

}  // namespace
}  // namespace amp::core
