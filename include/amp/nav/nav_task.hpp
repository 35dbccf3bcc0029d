#pragma once
#include <memory>

#include <Eigen/Core>

#include "amp/nav/world_timeline.hpp"
#include "amp/world/problem.hpp"

namespace amp::nav {

// What a navigation method needs of a problem: the world as it changes (its `events:` applied),
// the disc robot's radius, and where the robot starts and is sent.
struct NavTask {
  std::string name;  // the problem's name
  std::shared_ptr<const WorldTimeline> timeline;
  double robot_radius = 0.0;
  Eigen::Vector2d start = Eigen::Vector2d::Zero();
  Eigen::Vector2d goal = Eigen::Vector2d::Zero();
};

// The task of a loaded 2-D problem whose robot is a disc (a 2-coordinate state and a robot as wide
// as twice its reach). Throws ParameterError naming the problem file for a 3-D world, a robot that
// is not a disc, a bad `events:` list, or a start or goal where the disc is not free.
NavTask make_nav_task(const world::Problem& problem);

}  // namespace amp::nav
