// uas/uas_regions.cpp: UAS regions, the grown bounding boxes of the training clusters, their
// visibility figures and weights.
#include "amp/roadmap/uas/uas_regions.hpp"

#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "roadmap/test_worlds.hpp"

namespace amp::roadmap {
namespace {

TEST(ClusterStats, MatchHandComputedFigures) {
  // Cluster 0: visibilities 0, 0.5, 1 -> mean 0.5, sample sd 0.5; cluster 1: 0.25 alone -> sd 0.
  const auto s = cluster_stats({0.0, 0.25, 0.5, 1.0}, {0, 1, 0, 0}, 2);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].size, 3u);
  EXPECT_DOUBLE_EQ(s[0].size_percent, 75.0);
  EXPECT_DOUBLE_EQ(s[0].visibility_mean, 0.5);
  EXPECT_DOUBLE_EQ(s[0].visibility_std, 0.5);
  EXPECT_DOUBLE_EQ(s[0].visibility_min, 0.0);
  EXPECT_DOUBLE_EQ(s[0].visibility_max, 1.0);
  EXPECT_DOUBLE_EQ(s[1].size_percent, 25.0);
  EXPECT_DOUBLE_EQ(s[1].visibility_std, 0.0);
  EXPECT_DOUBLE_EQ(s[1].visibility_min, 0.25);
}

TEST(MakeRegions, GrowBoxesToTheRobotSizeClipThemAndTakeInUncoveredSeeds) {
  TrainingSet t;
  t.planar = true;
  t.positions = {{1, 1, 0}, {3, 2, 0}, {8, 8, 0}};  // cluster 0: two nodes; cluster 1: one (zero volume)
  t.visibility = {1.0, 0.5, 0.2};
  const Eigen::AlignedBox3d bounds(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(10, 10, 0));
  int extended = -1;
  const auto r = make_regions(t, {0, 0, 1}, 2, bounds, 1.0, 0.5, {}, &extended);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(extended, 0);
  // Cluster 0: [1,3]x[1,2] grown by 0.5 per side -> [0.5,3.5]x[0.5,2.5].
  EXPECT_TRUE(r[0].box.min().isApprox(Eigen::Vector3d(0.5, 0.5, 0)));
  EXPECT_TRUE(r[0].box.max().isApprox(Eigen::Vector3d(3.5, 2.5, 0)));
  EXPECT_EQ(r[0].members, (std::vector<std::size_t>{0, 1}));
  EXPECT_DOUBLE_EQ(r[0].stats.visibility_mean, 0.75);
  // Cluster 1: a point, grown by the margin to 1.0 wide: exactly the robot size.
  EXPECT_TRUE(r[1].box.min().isApprox(Eigen::Vector3d(7.5, 7.5, 0)));
  EXPECT_TRUE(r[1].box.max().isApprox(Eigen::Vector3d(8.5, 8.5, 0)));
  // No margin: the point still grows to the robot size (2.0 here), clipped by the bounds near a corner.
  TrainingSet corner = t;
  corner.positions[2] = {9.8, 9.8, 0};
  const auto r2 = make_regions(corner, {0, 0, 1}, 2, bounds, 2.0, 0.0, {}, nullptr);
  EXPECT_TRUE(r2[1].box.min().isApprox(Eigen::Vector3d(8.8, 8.8, 0)));
  EXPECT_TRUE(r2[1].box.max().isApprox(Eigen::Vector3d(10, 10, 0)));
  // A seed at (9, 1) lies in no box: the box of its nearest node's cluster (node 1, cluster 0) takes it in.
  const auto r3 = make_regions(t, {0, 0, 1}, 2, bounds, 1.0, 0.5, {Eigen::Vector3d(9, 1, 0)}, &extended);
  EXPECT_EQ(extended, 1);
  EXPECT_TRUE(r3[0].box.contains(Eigen::Vector3d(9, 1, 0)));
  EXPECT_FALSE(r3[1].box.contains(Eigen::Vector3d(9, 1, 0)));
}

// A region's weight is 1 + its members of visibility below 1/2 (the cc-expand threshold); members
// index the training set.
TEST(NarrowWeight, CountsTheRegionsMembersOfLowVisibility) {
  TrainingSet t;
  t.visibility = {0.0, 0.49, 0.5, 0.9, 0.1, 0.3};
  t.positions.resize(t.visibility.size(), Eigen::Vector3d::Zero());
  Region r;
  r.members = {0, 2, 3};  // 0.0 counts, 0.5 does not
  EXPECT_EQ(narrow_weight(r, t), 2.0);
  r.members = {1, 4, 5};
  EXPECT_EQ(narrow_weight(r, t), 4.0);
  r.members = {};
  EXPECT_EQ(narrow_weight(r, t), 1.0);
}

// The robot's size for regions: its bounding diameter, or 1% of the workspace's largest side for a
// point robot.
TEST(RegionRobotSize, DiameterOrOnePercentOfTheWorkspace) {
  const world::Problem arm = test::arm_problem();  // robot_radius 2 links of 2
  EXPECT_DOUBLE_EQ(region_robot_size(*arm.environment), 8.0);
  const world::Problem point = test::point_problem(true);  // workspace 10 x 10
  EXPECT_DOUBLE_EQ(region_robot_size(*point.environment), 0.1);
}

}  // namespace
}  // namespace amp::roadmap
