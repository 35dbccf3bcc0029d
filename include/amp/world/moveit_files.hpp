#pragma once
// MoveIt's PlanningScene and MotionPlanRequest messages as YAML, unchanged: the form robowflex
// writes for MotionBenchMaker (`type: box`, positions and quaternions as lists) and the plain
// ROS-message form (`type: 1`, `position: {x:, y:, z:}`).
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "amp/world/spatial_world.hpp"

namespace amp::world {

// Named joint values (a sensor_msgs/JointState's name and position lists).
using JointValues = std::map<std::string, double>;

// Pairs of names (links or objects) whose collisions the scene allows, either order.
class AllowedCollisions {
 public:
  void allow(const std::string& a, const std::string& b);
  bool allowed(const std::string& a, const std::string& b) const;
  bool empty() const { return pairs_.empty(); }

 private:
  std::set<std::pair<std::string, std::string>> pairs_;
};

struct MoveItScene {
  std::vector<Solid> objects;        // world frame
  std::vector<std::string> object_ids;  // one per solid: its collision object's id
  AllowedCollisions allowed;
  JointValues robot_state;
};

struct MoveItRequest {
  std::string group;
  JointValues start;
  std::vector<std::pair<std::string, double>> goal;  // joint_constraints in file order
  double allowed_planning_time = 0.0;               // 0: not given
};

// Throws FileError naming the file and the field: not YAML, a primitive that is not a box,
// sphere, cylinder (or a mesh of vertices and triangles), dimensions that do not fit the shape,
// attached objects, an object id repeated.
MoveItScene load_moveit_scene(const std::filesystem::path& file);
MoveItScene parse_moveit_scene(const std::string& yaml, const std::filesystem::path& label);
// Throws FileError: no joint goal, a pose goal ("not supported"), names and positions of unequal length.
MoveItRequest load_moveit_request(const std::filesystem::path& file);
MoveItRequest parse_moveit_request(const std::string& yaml, const std::filesystem::path& label);

}  // namespace amp::world
