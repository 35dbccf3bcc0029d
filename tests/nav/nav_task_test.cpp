#include "amp/nav/nav_task.hpp"

#include <string>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "support/bundled_problems.hpp"

namespace amp::nav {
namespace {

TEST(NavTask, DiscProblemsGiveTheirRadiusStartAndGoal) {
  const NavTask t = make_nav_task(test::bundled_problem("office-map.yaml"));
  EXPECT_DOUBLE_EQ(t.robot_radius, 0.25);
  EXPECT_EQ(t.start, Eigen::Vector2d(1.0, 1.0));
  EXPECT_EQ(t.goal, Eigen::Vector2d(9.0, 6.5));
  EXPECT_TRUE(t.timeline->events().empty());
  EXPECT_DOUBLE_EQ(make_nav_task(test::bundled_problem("movingai-rooms.yaml")).robot_radius, 0.4);
}

void expect_refused(const std::string& file, const std::string& words) {
  try {
    make_nav_task(test::bundled_problem(file));
    FAIL() << file << " was accepted";
  } catch (const ParameterError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(file), std::string::npos) << m;  // names the file
    EXPECT_NE(m.find(words), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
}

TEST(NavTask, RobotThatIsNotADiscIsRefused) { expect_refused("walls.yaml", "not a disc"); }
TEST(NavTask, ThreeDimensionalWorldIsRefused) { expect_refused("walls3d.yaml", "2-D"); }

}  // namespace
}  // namespace amp::nav
