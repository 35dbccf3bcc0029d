#include "amp/nav/world_timeline.hpp"

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/nav/grid_nav_world.hpp"
#include "amp/nav/polygon_nav_world.hpp"

namespace amp::nav {
namespace {

using V = Eigen::Vector2d;

WorldEvent cells_event(std::size_t step, ObstacleChange::Action action, CellRect r) {
  WorldEvent e;
  e.step = step;
  e.change.action = action;
  e.change.cells.push_back(r);
  return e;
}

TEST(WorldTimeline, MapEventsChangeAnswersAtTheirStep) {
  auto g = std::make_shared<world::OccupancyGrid>(10, 3, 1.0);
  const auto base = std::make_shared<const GridNavWorld>(g);
  // A door in column 5 closes at step 10 and opens again at step 20; given out of order.
  const WorldTimeline t(base, {cells_event(20, ObstacleChange::Action::kVanish, {5, 0, 5, 2}),
                               cells_event(10, ObstacleChange::Action::kAppear, {5, 0, 5, 2})});
  EXPECT_EQ(t.version_count(), 3u);
  const V p(0.5, 1.5);
  EXPECT_DOUBLE_EQ(t.at(0)->ray_cast(p, {1, 0}, 100), 9.5);
  EXPECT_DOUBLE_EQ(t.at(9)->ray_cast(p, {1, 0}, 100), 9.5);
  EXPECT_DOUBLE_EQ(t.at(10)->ray_cast(p, {1, 0}, 100), 4.5);
  EXPECT_DOUBLE_EQ(t.at(19)->ray_cast(p, {1, 0}, 100), 4.5);
  EXPECT_DOUBLE_EQ(t.at(20)->ray_cast(p, {1, 0}, 100), 9.5);
  EXPECT_EQ(t.version_at(15), 1u);
  EXPECT_EQ(t.at(0), t.base());
}

TEST(WorldTimeline, EventsOfOneStepMakeOneVersion) {
  const auto base = std::make_shared<const PolygonNavWorld>(world::Shapes2d{}, Eigen::AlignedBox2d(V(0, 0), V(4, 4)));
  WorldEvent a, b;
  a.step = b.step = 0;
  a.change.shapes.circles.push_back({{2, 2}, 0.5});
  b.change.shapes.circles.push_back({{3, 3}, 0.25});
  const WorldTimeline t(base, {a, b});
  EXPECT_EQ(t.version_count(), 2u);
  EXPECT_FALSE(t.at(0)->disc_free({2, 2}, 0.1));
  EXPECT_FALSE(t.at(0)->disc_free({3, 3}, 0.1));
  EXPECT_TRUE(t.base()->disc_free({2, 2}, 0.1));
}

TEST(WorldTimeline, AnEventThatCannotApplyIsNamed) {
  const auto base = std::make_shared<const PolygonNavWorld>(world::Shapes2d{}, Eigen::AlignedBox2d(V(0, 0), V(4, 4)));
  WorldEvent gone;
  gone.step = 3;
  gone.change.action = ObstacleChange::Action::kVanish;
  gone.change.shapes.circles.push_back({{2, 2}, 0.5});
  try {
    WorldTimeline(base, {gone});
    FAIL() << "expected ParameterError";
  } catch (const ParameterError& e) {
    EXPECT_NE(std::string(e.what()).find("events[0] (step 3)"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace amp::nav
