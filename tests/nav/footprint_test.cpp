// Footprints: the rectangle's disc cover by hand, checks at the heading in the lab's 60 cm door,
// turns in place, and the simulator driving a rectangular unicycle.
#include "amp/nav/footprint.hpp"

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"
#include "amp/nav/grid_nav_world.hpp"
#include "amp/nav/simulator.hpp"
#include "amp/nav/unicycle_disc.hpp"
#include "nav/lab_world.hpp"

namespace amp::nav {
namespace {

using V = Eigen::Vector2d;
constexpr double kPi = std::numbers::pi;

TEST(Footprint, RectangleCoverByHand) {
  // 0.7 m x 0.54 m: the longest slice keeping the corner disc within 5 mm of the half width is
  // 2 sqrt(0.275^2 - 0.27^2) = 0.1044 m, so n = ceil(0.7 / 0.1044) = 7 slices of 0.1 m, discs at
  // -0.3, -0.2, ..., 0.3 of radius hypot(0.27, 0.05) = 0.274591.
  const Footprint f = Footprint::rectangle(0.7, 0.54);
  ASSERT_EQ(f.centres().size(), 7u);
  EXPECT_NEAR(f.centres().front().x(), -0.3, 1e-12);
  EXPECT_NEAR(f.centres().back().x(), 0.3, 1e-12);
  EXPECT_NEAR(f.disc_radius(), std::hypot(0.27, 0.05), 1e-12);
  EXPECT_NEAR(f.centre_reach(), 0.3, 1e-12);
  EXPECT_FALSE(f.is_disc());
  // Every point of the rectangle lies in some disc (a grid of points, corners included).
  for (int i = 0; i <= 70; ++i) {
    for (int j = 0; j <= 54; ++j) {
      const V p(-0.35 + 0.01 * i, -0.27 + 0.01 * j);
      bool covered = false;
      for (const V& c : f.centres()) covered = covered || (p - c).norm() <= f.disc_radius() + 1e-12;
      EXPECT_TRUE(covered) << p.transpose();
    }
  }
  const Footprint d = Footprint::disc(0.27);
  EXPECT_TRUE(d.is_disc());
  EXPECT_EQ(d.centre_reach(), 0.0);
  EXPECT_THROW(Footprint::rectangle(0.4, 0.54), ParameterError);  // driven lengthwise: length >= width
  EXPECT_THROW(Footprint::disc(0.0), ParameterError);
}

TEST(Footprint, CheckedAtItsHeadingInTheDoor) {
  const auto world = test::lab();  // a 60 cm door at x 1.7-2.3 in the wall y 3.5-3.6
  const Footprint f = Footprint::rectangle(0.7, 0.54);
  const V door(2.0, 3.55);
  EXPECT_TRUE(f.free(*world, door, kPi / 2));  // lengthwise through the door
  EXPECT_FALSE(f.free(*world, door, 0.0));     // across it
  EXPECT_GT(f.clearance(*world, door, kPi / 2), 0.0);
  EXPECT_LT(f.clearance(*world, door, 0.0), 0.0);
  // 2.5 mm short of the 3 cm each side: the cover is 5.5 mm a side wider than the rectangle.
  EXPECT_NEAR(f.clearance(*world, door, kPi / 2), 0.3 - f.disc_radius(), 1e-9);
  // Turning in place: free in the open room, not in the door.
  EXPECT_TRUE(f.turn_free(*world, V(2.0, 1.5), 0.0, 2.0 * kPi));
  EXPECT_FALSE(f.turn_free(*world, door, kPi / 2, kPi / 2));
  EXPECT_FALSE(f.turn_free(*world, door, kPi / 2, -0.3));
  // A disc turns wherever it fits.
  EXPECT_TRUE(Footprint::disc(0.27).turn_free(*world, door, 0.0, kPi));
}

// The capped clearance DWA scores with is min(exact, cap) for discs and rectangles, overlapping,
// in the door and in the open; a polygon world answers through the default, a map through its own.
TEST(Footprint, CappedClearanceIsTheExactClearanceCapped) {
  const auto world = test::lab();
  core::Rng rng(3);
  int capped = 0, below = 0;
  for (const Footprint& f : {Footprint::disc(0.27), Footprint::rectangle(0.7, 0.54)}) {
    for (int i = 0; i < 300; ++i) {
      const V p(rng.uniform(0.0, 4.0), rng.uniform(0.0, 5.0));
      const double heading = rng.uniform(-kPi, kPi), exact = f.clearance(*world, p, heading);
      for (const double cap : {0.005, 0.1, 1.0}) {
        ASSERT_EQ(f.clearance_up_to(*world, p, heading, cap), std::min(exact, cap)) << p.transpose() << " " << cap;
        (exact >= cap ? capped : below) += 1;
      }
    }
  }
  EXPECT_GT(capped, 300);
  EXPECT_GT(below, 300);
}

TEST(Footprint, TheSimulatorNeverTurnsARectangleIntoTheDoorFrame) {
  const auto timeline = std::make_shared<const WorldTimeline>(test::lab(), std::vector<WorldEvent>{});
  UnicycleDiscSettings robot;
  robot.length = 0.7;
  const auto unicycle = std::make_shared<const UnicycleDisc>(robot);
  RobotState s;
  s.position = V(2.0, 3.55);
  s.heading = kPi / 2;
  Simulator sim(timeline, unicycle, s);
  EXPECT_FALSE(sim.footprint().is_disc());
  core::Rng rng(1);
  for (int i = 0; i < 20; ++i) sim.step(V(0.0, 1.0), rng);  // turn on the spot, in the door
  EXPECT_GT(sim.blocked_moves(), 0u);
  EXPECT_TRUE(sim.footprint().free(sim.world(), sim.state().position, sim.state().heading));
  // It turned only as far as the frame lets it: about 0.297 rad in a wall 10 cm thick (a turn of
  // 0.3 is refused by turn_free above).
  EXPECT_GT(sim.state().heading - kPi / 2, 0.25);
  EXPECT_LT(sim.state().heading - kPi / 2, 0.3);
  // Straight on, it leaves the door into the corridor unhindered.
  const std::size_t blocked = sim.blocked_moves();
  RobotState aligned = sim.state();
  aligned.heading = kPi / 2;
  sim.place(aligned);
  for (int i = 0; i < 20; ++i) sim.step(V(0.26, 0.0), rng);
  EXPECT_EQ(sim.blocked_moves(), blocked);
  EXPECT_GT(sim.state().position.y(), 3.9);
}

}  // namespace
}  // namespace amp::nav
