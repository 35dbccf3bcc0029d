#include "amp/nav/sins/clutter_world.hpp"

#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"
#include "amp/nav/polygon_nav_world.hpp"
#include "amp/nav/reference_grid.hpp"

namespace amp::nav {
namespace {

using V = Eigen::Vector2d;
constexpr double kPi = std::numbers::pi;

void expect_same(const ClutterWorld& a, const ClutterWorld& b) {
  ASSERT_EQ(a.circles.size(), b.circles.size());
  for (std::size_t i = 0; i < a.circles.size(); ++i) {
    EXPECT_EQ(a.circles[i].center, b.circles[i].center);
    EXPECT_EQ(a.circles[i].radius, b.circles[i].radius);
  }
  EXPECT_EQ(a.start, b.start);
  EXPECT_EQ(a.goal, b.goal);
  EXPECT_EQ(a.optimal_length, b.optimal_length);
  EXPECT_EQ(a.clutter, b.clutter);
  EXPECT_EQ(a.rejected, b.rejected);
}

// The covered share of the box by uniform samples, independent of the generator's raster.
double monte_carlo_clutter(const ClutterWorld& w, double width, double height, int samples) {
  core::Rng rng(12345);
  int inside = 0;
  for (int k = 0; k < samples; ++k) {
    const V p(rng.uniform(0.0, width), rng.uniform(0.0, height));
    for (const world::Circle& c : w.circles) {
      if ((p - c.center).squaredNorm() <= c.radius * c.radius) {
        ++inside;
        break;
      }
    }
  }
  return static_cast<double>(inside) / samples;
}

// The 8-connected grid's free-space distance: what "straight" means on the reference grid.
double octile(const V& d) {
  const double a = std::abs(d.x()), b = std::abs(d.y());
  return std::max(a, b) + (std::sqrt(2.0) - 1.0) * std::min(a, b);
}

TEST(ClutterWorld, SameSeedGivesSameWorlds) {
  ClutterWorldSequence a(7, {}), b(7, {});
  for (int i = 0; i < 3; ++i) expect_same(a.next(), b.next());
  EXPECT_EQ(a.index(), 3);
  ClutterWorldSequence c(8, {});
  c.seek(2);
  EXPECT_NE(c.next().start, a.at(2).start);
}

TEST(ClutterWorld, WorldDependsOnlyOnSeedAndIndex) {
  ClutterWorldSequence walked(11, {}), skipped(11, {});
  for (int i = 0; i < 3; ++i) walked.next();
  skipped.seek(3);
  const ClutterWorld w3 = walked.next();
  expect_same(w3, skipped.next());
  expect_same(w3, ClutterWorldSequence(11, {}).at(3));
  EXPECT_EQ(skipped.index(), 4);
  EXPECT_THROW(skipped.seek(-1), ParameterError);
}

TEST(ClutterWorld, AchievedClutterMatchesTargetAndMonteCarlo) {
  const ClutterWorldSettings defaults;
  const double biggest = kPi * defaults.max_radius * defaults.max_radius / (defaults.width * defaults.height);
  for (const double target : {0.10, 0.25, 0.50}) {
    ClutterWorldSettings s;
    s.clutter = target;
    ClutterWorldSequence seq(3, s);
    for (int i = 0; i < 2; ++i) {
      const ClutterWorld w = seq.next();
      SCOPED_TRACE("clutter " + std::to_string(target) + ", world " + std::to_string(i));
      EXPECT_GE(w.clutter, target);
      EXPECT_LE(w.clutter, target + biggest);  // only the last circle overshoots
      // 40000 samples: standard error <= 0.0025; the raster is finer than that.
      EXPECT_NEAR(monte_carlo_clutter(w, s.width, s.height, 40000), w.clutter, 0.01);
    }
  }
}

TEST(ClutterWorld, StartAndGoalKeepTheMarginAreFarApartAndConnected) {
  ClutterWorldSettings s;
  s.clutter = 0.4;
  ClutterWorldSequence seq(5, s);
  const double clear = s.clearance();
  for (int i = 0; i < 4; ++i) {
    const ClutterWorld w = seq.next();
    for (const V& p : {w.start, w.goal}) {
      EXPECT_TRUE(w.world->disc_free(p, clear));  // circles and box
      for (const world::Circle& c : w.circles) EXPECT_GE((p - c.center).norm(), c.radius + clear);
    }
    EXPECT_LE(w.start.x(), 0.15 * s.width);
    EXPECT_GE(w.goal.x(), 0.85 * s.width);
    ASSERT_TRUE(std::isfinite(w.optimal_length));
    ReferenceGrid grid(*w.world, s.robot_radius, s.reference_cell);
    EXPECT_EQ(grid.shortest_length(w.start, w.goal), w.optimal_length);
    EXPECT_GE(w.optimal_length, (w.goal - w.start).norm());
  }
  EXPECT_GE(seq.rejected_total(), 0);
}

TEST(ClutterWorld, TallBoxPutsStartAndGoalAtItsEnds) {
  ClutterWorldSettings s;
  s.width = 10.0;
  s.height = 30.0;
  s.clutter = 0.1;
  const ClutterWorld w = ClutterWorldSequence(2, s).next();
  EXPECT_LE(w.start.y(), 0.15 * s.height);
  EXPECT_GE(w.goal.y(), 0.85 * s.height);
  EXPECT_GE(w.start.x(), s.clearance());
  EXPECT_LE(w.start.x(), s.width - s.clearance());
}

TEST(ClutterWorld, RejectedWorldsAreCountedInTheTotal) {
  ClutterWorldSettings s;
  s.width = s.height = 20.0;
  s.clutter = 0.55;  // near percolation of the inflated circles: some worlds are cut off
  ClutterWorldSequence seq(1, s);
  int sum = 0, max_rejected = 0;
  for (int i = 0; i < 12; ++i) {
    const ClutterWorld w = seq.next();
    sum += w.rejected;
    max_rejected = std::max(max_rejected, w.rejected);
  }
  EXPECT_EQ(seq.rejected_total(), sum);
  EXPECT_GT(max_rejected, 0);
}

// Hand case: one circle far above a horizontal line: the grid-shortest path is the straight line,
// exactly between cell centres, and within sqrt(2) cells elsewhere (each end adds its distance to
// its cell's centre, up to half a cell's diagonal).
TEST(ClutterWorld, OpenLineIsStraight) {
  ClutterWorldSettings s;
  s.width = s.height = 10.0;
  s.reference_cell = 0.1;  // cell centres at 0.05 + 0.1 k
  const std::vector<world::Circle> far_above = {{V(5, 9), 0.5}};
  const ClutterWorld centred = assemble_clutter_world(far_above, V(1.05, 5.05), V(8.95, 5.05), s);
  EXPECT_NEAR(centred.optimal_length, 7.9, 1e-9);
  EXPECT_NEAR(centred.clutter, kPi * 0.25 / 100.0, 2e-4);
  EXPECT_EQ(centred.rejected, 0);
  const ClutterWorld corners = assemble_clutter_world(far_above, V(1, 5), V(9, 5), s);
  EXPECT_GE(corners.optimal_length, 8.0);
  EXPECT_LE(corners.optimal_length, 8.0 + std::sqrt(2.0) * s.reference_cell + 1e-9);
}

// Hand case: a unit circle between start and goal, 4 m from each. The disc's shortest path wraps the
// circle grown by the robot radius (R = 1.25): two tangents of sqrt(16 - R^2) and the arc between
// them, R (pi - 2 acos(R / 4)). The 8-connected grid pays at most 1 / cos(22.5 deg) ~ 1.0824 more.
TEST(ClutterWorld, DetourAroundACircleIsBetweenEuclideanAndOctile) {
  ClutterWorldSettings s;
  s.width = s.height = 10.0;
  const ClutterWorld w = assemble_clutter_world({{V(5, 5), 1.0}}, V(1, 5), V(9, 5), s);
  const double r = 1.25;
  const double exact = 2.0 * std::sqrt(16.0 - r * r) + r * (kPi - 2.0 * std::acos(r / 4.0));
  EXPECT_GE(w.optimal_length, exact - s.reference_cell);
  EXPECT_LE(w.optimal_length, exact / std::cos(kPi / 8.0) + 2.0 * s.reference_cell);
  EXPECT_GT(w.optimal_length, 8.0 + 0.2);  // really a detour
}

TEST(ClutterWorld, CutOffHandCaseHasNoLength) {
  ClutterWorldSettings s;
  s.width = s.height = 10.0;
  const ClutterWorld w = assemble_clutter_world({{V(5, 5), 6.0}}, V(1, 5), V(9, 5), s);
  EXPECT_TRUE(std::isinf(w.optimal_length));
}

// Tiny clutter: one small circle. Where it stays clear of the start-goal rectangle, the grid-shortest
// length is the grid's straight line (octile distance), within the cell offsets.
TEST(ClutterWorld, TinyClutterGivesTheStraightGridLength) {
  ClutterWorldSettings s;
  s.clutter = 1e-4;
  s.min_radius = s.max_radius = 0.5;
  ClutterWorldSequence seq(9, s);
  int checked = 0;
  for (int i = 0; i < 10; ++i) {
    const ClutterWorld w = seq.next();
    ASSERT_EQ(w.circles.size(), 1u);
    const world::Circle& c = w.circles[0];
    Eigen::AlignedBox2d band(w.start.cwiseMin(w.goal), w.start.cwiseMax(w.goal));
    const double away = c.radius + s.robot_radius + 2.0 * s.reference_cell;
    if (band.exteriorDistance(c.center) < away) continue;
    ++checked;
    const double straight = (w.goal - w.start).norm();
    EXPECT_GE(w.optimal_length, straight);
    EXPECT_NEAR(w.optimal_length, octile(w.goal - w.start), 3.0 * s.reference_cell);
  }
  EXPECT_GE(checked, 3);
}

TEST(ClutterWorld, UnreachableClutterThrowsOneLine) {
  ClutterWorldSettings s;
  s.clutter = 0.95;
  s.min_radius = 3.0;
  s.max_radius = 6.0;
  s.max_tries = 3;
  core::Rng rng(4);
  try {
    make_clutter_world(s, rng);
    FAIL() << "expected ParameterError";
  } catch (const ParameterError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("clutter 0.95: ", 0), 0u) << m;
    EXPECT_NE(m.find("3 tries"), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
}

TEST(ClutterWorld, BadSettingsNameTheSetting) {
  const std::vector<std::pair<std::function<void(ClutterWorldSettings&)>, std::string>> cases = {
      {[](ClutterWorldSettings& s) { s.clutter = 0.0; }, "clutter"},
      {[](ClutterWorldSettings& s) { s.clutter = 1.0; }, "clutter"},
      {[](ClutterWorldSettings& s) { s.clutter = std::nan(""); }, "clutter"},
      {[](ClutterWorldSettings& s) { s.min_radius = 0.0; }, "min_radius"},
      {[](ClutterWorldSettings& s) { s.max_radius = 0.4; }, "max_radius"},
      {[](ClutterWorldSettings& s) { s.width = -1.0; }, "width"},
      {[](ClutterWorldSettings& s) { s.height = 0.0; }, "height"},
      {[](ClutterWorldSettings& s) { s.robot_radius = 0.0; }, "robot_radius"},
      {[](ClutterWorldSettings& s) { s.start_goal_margin = -0.1; }, "start_goal_margin"},
      {[](ClutterWorldSettings& s) { s.reference_cell = 0.0; }, "reference_cell"},
      {[](ClutterWorldSettings& s) { s.reference_cell = 1e-4; }, "reference_cell"},
      {[](ClutterWorldSettings& s) { s.max_tries = 0; }, "max_tries"},
      {[](ClutterWorldSettings& s) { s.height = 1.5; }, "robot_radius + start_goal_margin"},
  };
  for (const auto& [spoil, name] : cases) {
    ClutterWorldSettings s;
    spoil(s);
    try {
      ClutterWorldSequence seq(1, s);
      ADD_FAILURE() << "expected an error naming " << name;
    } catch (const ParameterError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find(name), std::string::npos) << m;
      EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    }
  }
}

TEST(ClutterWorld, SetClutterChangesTheWorldsFromTheNextOn) {
  ClutterWorldSequence seq(21, {});
  const ClutterWorld before = seq.next();
  EXPECT_LT(before.clutter, 0.3);
  seq.set_clutter(0.5);
  EXPECT_EQ(seq.settings().clutter, 0.5);
  const ClutterWorld after = seq.next();
  EXPECT_GE(after.clutter, 0.5);
  // The same stream: the start is drawn before the circles (unless a world was redrawn).
  const ClutterWorld unchanged = ClutterWorldSequence(21, {}).at(1);
  if (after.rejected == 0 && unchanged.rejected == 0) {
    EXPECT_EQ(after.start, unchanged.start);
  }
  EXPECT_THROW(seq.set_clutter(1.5), ParameterError);
  EXPECT_EQ(seq.settings().clutter, 0.5);
}

}  // namespace
}  // namespace amp::nav
