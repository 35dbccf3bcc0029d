// Edge certification's step on arms (ValidityChecker::free_share): each part's and each self pair's
// motion per joint step, worked out by hand on the two-link arm of tests/data/arm/two_link; and on
// the bundled Panda problems, that the share is never below the whole-robot bound it replaces
// (free_radius / motion_bound) and that every state within it is valid.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "amp/core/counters.hpp"
#include "amp/core/rng.hpp"
#include "amp/world/arm_environment.hpp"
#include "amp/world/arm_problem.hpp"
#include "support/source_tree.hpp"

namespace amp::world {
namespace {

namespace fs = std::filesystem;

const ArmRobot& robot_of(const Problem& p) { return dynamic_cast<const ArmEnvironment&>(*p.environment).robot(); }

std::vector<double> part_row(const ArmRobot& r, std::size_t part) {
  std::vector<double> out;
  for (int k = 0; k < r.kinematics().dof(); ++k) out.push_back(r.part_motion(part, k));
  return out;
}

std::vector<double> pair_row(const ArmRobot& r, std::size_t pair) {
  std::vector<double> out;
  for (int k = 0; k < r.kinematics().dof(); ++k) out.push_back(r.pair_motion(pair, k));
  return out;
}

void expect_row(const std::vector<double>& got, const std::vector<double>& want, const std::string& what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  for (std::size_t k = 0; k < got.size(); ++k) EXPECT_NEAR(got[k], want[k], 1e-12) << what << ", joint " << k;
}

// Joints: shoulder (revolute, origin 0.1 up), slide (prismatic along x, origin (0.5, 0, 0.05),
// travel 0.3), wrist (continuous, origin 0.2 along x), tool_joint (fixed, 0.4 along x). Parts: base
// box, link1 box (0.5 x 0.1 x 0.1 centred at (0.25, 0, 0.05)), link2 cylinder, link3 box, tool sphere.
TEST(ArmFreeShare, CoefficientsByHand) {
  const fs::path dir = fs::path(AMP_SOURCE_DIR) / "tests" / "data" / "arm" / "two_link";
  const Problem p = load_arm_problem({dir / "two_link.urdf", dir / "two_link.srdf", dir / "scene.yaml", dir / "request.yaml", {}, {}});
  const ArmRobot& robot = robot_of(p);
  ASSERT_EQ(robot.kinematics().dof(), 3);
  ASSERT_EQ(robot.part_count(), 5u);
  const int link1 = robot.model().link_index("link1");
  const int tool = robot.model().link_index("tool");
  // The base moves with no joint.
  expect_row(part_row(robot, 0), {0, 0, 0}, "base");
  // link1: only the shoulder, by the box's farthest corner (0.5, 0.05, 0.1) from its origin.
  const double link1_reach = std::sqrt(0.5 * 0.5 + 0.05 * 0.05 + 0.1 * 0.1);
  expect_row(part_row(robot, 1), {link1_reach, 0, 0}, "link1");
  // The tool sphere (radius 0.03): the wrist turns it at 0.4 + 0.03; the slide moves it by its step;
  // the shoulder at 0.43 + 0.2 + |(0.5, 0, 0.05)| + 0.3.
  const double wrist = 0.43, shoulder = 0.43 + 0.2 + std::hypot(0.5, 0.05) + 0.3;
  expect_row(part_row(robot, 4), {shoulder, 1.0, wrist}, "tool");
  // Self pairs: link1 against the tool moves only by the joints between them (slide and wrist);
  // the shoulder turns both alike.
  const auto& pairs = robot.self_part_pairs();
  bool found = false;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const int la = robot.part_link(static_cast<std::size_t>(pairs[i].first));
    const int lb = robot.part_link(static_cast<std::size_t>(pairs[i].second));
    if (la == link1 && lb == tool) {
      expect_row(pair_row(robot, i), {0, 1.0, wrist}, "link1-tool");
      found = true;
    }
  }
  EXPECT_TRUE(found);
}

// On each bundled Panda problem, 200 seeded (s, a, b): s valid, a and b drawn in the joint limits.
// The share is at least free_radius(s) / motion_bound(a, b); the states s + tau (b - a) for tau in
// [-share, share] (20 of them) are valid.
TEST(ArmFreeShare, NeverBelowTheWholeRobotBoundAndSound) {
  const fs::path panda = fs::path(AMP_SOURCE_DIR) / "problems" / "arms" / "panda";
  const ArmDescription robot = load_arm_description(panda / "panda.urdf", panda / "panda.srdf");
  int measured = 0, larger = 0;
  double gain_sum = 0.0;
  for (const char* family : {"box", "table_pick", "bookshelf_small"}) {
    const fs::path scenes = panda / "scenes" / family;
    const Problem p = load_arm_problem(robot, scenes / "scene0001.yaml", scenes / "request0001.yaml");
    core::Counters counters;
    const auto checker = p.environment->make_checker(counters);
    core::Rng rng(35);
    State s, a, b, moved;
    for (int n = 0; n < 200;) {
      p.space->sample_uniform(rng, s);
      p.space->sample_uniform(rng, a);
      p.space->sample_uniform(rng, b);
      if (!checker->is_valid(s)) continue;
      ++n;
      const double share = checker->free_share(s, a, b);
      const double whole = checker->free_radius(s) / checker->motion_bound(a, b);
      ASSERT_GT(share, 0.0) << family << " #" << n;
      EXPECT_GE(share, whole * (1.0 - 1e-9)) << family << " #" << n;
      ++measured;
      larger += share > whole * 1.01 ? 1 : 0;
      gain_sum += share / whole;
      for (int k = -10; k <= 10; ++k) {
        const double tau = 0.99 * share * k / 10.0;
        moved = s + tau * (b - a);
        if (!p.space->in_bounds(moved)) continue;
        EXPECT_TRUE(checker->is_valid(moved)) << family << " #" << n << ": tau " << tau << " of share " << share;
      }
    }
  }
  std::cout << "[ share    ] larger than the whole-robot bound in " << larger << " of " << measured
            << " draws; mean ratio " << gain_sum / measured << "\n";
}

}  // namespace
}  // namespace amp::world
