#include "amp/nav/policy/footprint_drive.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/unicycle_space.hpp"
#include "amp/nav/footprint.hpp"
#include "amp/nav/policy/policy_search.hpp"
#include "nav/lab_world.hpp"

namespace amp::nav {
namespace {

using V = Eigen::Vector2d;
using test::lab;
constexpr double kPi = std::numbers::pi;

State waypoint(double x, double y) { return core::UnicycleSpace::make_state(x, y, 0.0, 0.2, 0.0); }
V xy(const State& w) { return {w[0], w[1]}; }

// The lab's door is x 1.7-2.3 in the wall y 3.5-3.6; the paper's robot is 0.7 m x 0.54 m.
const Footprint kRobot = Footprint::rectangle(0.7, 0.54);

// The footprint's least clearance along segment k, sampled every millimetre.
double room_on(const PolicyValue& value, const std::vector<State>& w, std::size_t k) {
  const V a = xy(w[k]), b = xy(w[k + 1]);
  const double heading = std::atan2(b.y() - a.y(), b.x() - a.x());
  double least = 1e9;
  const int n = static_cast<int>((b - a).norm() / 0.001);
  for (int i = 0; i <= n; ++i) least = std::min(least, kRobot.clearance(value.world(), a + (b - a) * i / n, heading));
  return least;
}

TEST(FootprintDrive, TheStartTurnIsFromFacingTheGoal) {
  const auto world = lab();
  const PolicyValue value(*world, kRobot);
  // In the middle of the room the body turns anywhere; in the door, facing the goal across it
  // (east) it does not even fit, whatever the path's first heading.
  EXPECT_TRUE(turn_drivable(value, {waypoint(2.0, 2.0), waypoint(3.0, 2.5), waypoint(2.0, 1.0)}, 0));
  EXPECT_FALSE(turn_drivable(value, {waypoint(2.0, 3.55), waypoint(2.0, 4.5), waypoint(3.5, 3.55)}, 0));
  EXPECT_TRUE(turn_drivable(value, {waypoint(2.0, 3.55), waypoint(2.0, 4.5), waypoint(2.0, 4.6)}, 0));
}

TEST(FootprintDrive, ASlantedDoorCrossingIsSquaredUp) {
  const auto world = lab();
  const PolicyValue value(*world, kRobot);
  // Through the door's centre at 14 degrees from square: drivable, with under a centimetre to spare.
  // (The cover's end discs reach 0.27 m beyond the body's ends: the ends stay 0.6 m from the walls.)
  const double slant = 14.0 * kPi / 180.0;
  const V centre(2.0, 3.55), along(std::sin(slant), std::cos(slant));
  std::vector<State> w = {waypoint(centre.x() - 0.9 * along.x(), centre.y() - 0.9 * along.y()),
                          waypoint(centre.x() + 0.9 * along.x(), centre.y() + 0.9 * along.y())};
  ASSERT_TRUE(policy_free(value, w));
  const double before = room_on(value, w, 0);
  ASSERT_LT(before, 0.01);
  const std::vector<State> slanted = w;
  EXPECT_EQ(square_crossings(value, w, 0.05), 1);
  // Start, A, B, goal: the start and the goal stay, and A -> B crosses square-on through the middle,
  // with the room of a square crossing: 0.3 m from the door's middle to its frame, less the cover's
  // discs' radius, sqrt(0.27^2 + 0.05^2).
  ASSERT_EQ(w.size(), 4u);
  EXPECT_EQ(xy(w.front()), xy(slanted.front()));
  EXPECT_EQ(xy(w.back()), xy(slanted.back()));
  EXPECT_TRUE(policy_free(value, w));
  const V a = xy(w[1]), b = xy(w[2]);
  EXPECT_LT(a.y(), 3.5 - 0.35);  // the body is out of the door when it turns
  EXPECT_GT(b.y(), 3.6 + 0.35);
  EXPECT_NEAR(std::atan2(b.y() - a.y(), b.x() - a.x()), kPi / 2, 1.0 * kPi / 180.0);
  EXPECT_NEAR(a.x() + (3.55 - a.y()) / (b.y() - a.y()) * (b.x() - a.x()), 2.0, 0.0125);
  EXPECT_GT(room_on(value, w, 1), before + kMinCrossingGain);
  EXPECT_NEAR(room_on(value, w, 1), 0.3 - std::hypot(0.27, 0.05), 0.002);
  // Deterministic, and a square crossing is left alone.
  std::vector<State> again = slanted;
  square_crossings(value, again, 0.05);
  EXPECT_EQ(again, w);
  std::vector<State> square = {waypoint(2.0, 2.7), waypoint(2.0, 4.4)};
  EXPECT_EQ(square_crossings(value, square, 0.05), 0);
  EXPECT_EQ(square.size(), 2u);
  // A disc has no heading to square.
  std::vector<State> disc = slanted;
  EXPECT_EQ(square_crossings(PolicyValue(*world, 0.27), disc, 0.05), 0);
}

TEST(FootprintDrive, AJogInTheDoorIsDroppedAndATurnInItMoved) {
  const auto world = lab();
  const PolicyValue value(*world, kRobot);
  // A grid path's one-cell jog inside the door: the body cannot drive its diagonal there, and the
  // slant of 2.2 degrees without it leaves room.
  std::vector<State> jog = {waypoint(1.98, 2.5), waypoint(1.98, 3.5), waypoint(2.02, 3.54), waypoint(2.02, 4.3)};
  ASSERT_FALSE(policy_free(value, jog));
  ASSERT_TRUE(make_drivable(value, jog, 0.05));
  ASSERT_EQ(jog.size(), 3u);
  EXPECT_TRUE(policy_free(value, jog));
  EXPECT_EQ(xy(jog[0]), V(1.98, 2.5));
  EXPECT_EQ(xy(jog[1]), V(2.02, 3.54));
  EXPECT_EQ(xy(jog[2]), V(2.02, 4.3));
  // A right-angle turn inside the door (the corridor above is 1.4 m deep) moves on along its
  // incoming segment, out of the door, to the first place 5 cm apart where it is drivable: 0.55 m on.
  std::vector<State> corner = {waypoint(2.0, 2.5), waypoint(2.0, 3.55), waypoint(3.3, 4.3)};
  ASSERT_FALSE(policy_free(value, corner));
  ASSERT_TRUE(make_drivable(value, corner, 0.05));
  EXPECT_TRUE(policy_free(value, corner));
  ASSERT_EQ(corner.size(), 3u);
  EXPECT_DOUBLE_EQ(corner[1][0], 2.0);
  EXPECT_NEAR(corner[1][1], 4.1, 1e-12);
  EXPECT_NEAR(corner[0][2], kPi / 2, 1e-12);  // headings follow the new segments
  // A turn no place near can make (the door closed) is reported.
  const auto closed = lab(false);
  std::vector<State> shut = {waypoint(2.0, 2.5), waypoint(2.0, 3.55), waypoint(2.0, 4.5)};
  EXPECT_FALSE(make_drivable(PolicyValue(*closed, kRobot), shut, 0.05));
}

}  // namespace
}  // namespace amp::nav
