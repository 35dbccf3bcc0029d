#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "amp/world/shapes2d.hpp"

namespace amp::core {
class Rng;
}

namespace amp::nav {

class PolygonNavWorld;

// The worlds of SINS's experiments (Ram & Santamaria 1993, Sec. 4; SPEC section 5): a box with
// random circles covering a requested fraction of it, a start and a destination.
struct ClutterWorldSettings {
  double width = 40.0, height = 40.0;          // the box [0, width] x [0, height], m
  double clutter = 0.25;                       // target fraction of the box covered, in (0, 1)
  double min_radius = 0.5, max_radius = 2.0;   // circle radii, uniform in [min, max]
  double robot_radius = 0.25;                  // the disc that must get from start to goal
  double start_goal_margin = 0.5;              // start/goal discs keep this far from circles and box
  double reference_cell = 0.2;                 // ReferenceGrid cell: connectivity and optimal_length (0.1 m cost 16-22 ms a world at 25%, 0.2 m 5-7 ms; optimal/straight 1.102 against 1.112)
  int max_tries = 100;                         // worlds drawn for one index before giving up

  // Throws ParameterError (one line naming the setting) for clutter outside (0, 1), radii not
  // 0 < min <= max, sizes, robot_radius or reference_cell not > 0, margin < 0, max_tries < 1, or a
  // box with no room for the start and goal discs (each side > 2 (robot_radius + margin)).
  void validate() const;
  // robot_radius + start_goal_margin: how far start and goal stay from every circle and the box.
  double clearance() const { return robot_radius + start_goal_margin; }
  // These settings with the world's lengths (the box, the circles' radii) times `factor`; the robot
  // (its radius and margin) and the reference cell stay: the world's scale against the robot.
  ClutterWorldSettings scaled(double factor) const {
    ClutterWorldSettings s = *this;
    s.width *= factor;
    s.height *= factor;
    s.min_radius *= factor;
    s.max_radius *= factor;
    return s;
  }
};

struct ClutterWorld {
  std::shared_ptr<const PolygonNavWorld> world;  // the circles in the box
  std::vector<world::Circle> circles;
  Eigen::Vector2d start = Eigen::Vector2d::Zero(), goal = Eigen::Vector2d::Zero();
  // ReferenceGrid::shortest_length at reference_cell for the robot disc (octile, so up to ~8% above
  // the Euclidean shortest path); +infinity only from assemble_clutter_world on a cut-off world.
  double optimal_length = 0.0;
  double clutter = 0.0;  // the achieved covered fraction (clutter_fraction), >= the target
  int rejected = 0;      // worlds drawn for this one and thrown away (cut off, or target not reached)
};

// The fraction of the box [0, width] x [0, height] covered by the union of the circles, clipped to
// the box: the share of raster cells whose centre lies in some circle. The raster has cells of about
// `cell` (rounded so that a whole number of them tiles each side exactly); the error is of the
// order of the union's perimeter times `cell` over the area, below 0.1 % for the defaults.
double clutter_fraction(const std::vector<world::Circle>& circles, double width, double height, double cell);

// A world from given circles, start and goal (hand-made cases, and the last step of drawing one):
// the achieved clutter on the raster of `settings.reference_cell / 2`, and optimal_length
// (+infinity when the robot disc cannot get from start to goal). rejected = 0. Does not check that
// start and goal keep the margin. Throws ParameterError for invalid settings or circles.
ClutterWorld assemble_clutter_world(std::vector<world::Circle> circles, const Eigen::Vector2d& start,
                                    const Eigen::Vector2d& goal, const ClutterWorldSettings& settings);

// One world drawn from `rng`. Start and goal first: along the box's longer side (x on a tie) the
// start lies in the first 15 % and the goal in the last 15 % (so at least 70 % of it apart), across
// it uniform, each at least clearance() from the box. Then circles, centre uniform in the box and
// radius uniform, are drawn; one coming nearer than clearance() to the start or goal is redrawn, so
// the clutter is reached elsewhere. Circles are added until the covered fraction, measured on the
// raster of reference_cell / 2 as clutter_fraction does, reaches the target (the last one
// overshoots). A world whose start and goal are not connected for the robot disc on the
// ReferenceGrid, or whose target cannot be reached (1000 draws in a row adding nothing: the gaps
// left are all beside the start or goal), is redrawn from the same rng and counted in `rejected`;
// a cut-off world is mostly recognised by a cheap, permissive flood fill before any ReferenceGrid is
// built (it never rejects a world the ReferenceGrid would connect, so the results are the same).
// Throws ParameterError for invalid settings, and after max_tries failures ("clutter 0.9: no world
// with a free path in 100 tries").
ClutterWorld make_clutter_world(const ClutterWorldSettings& settings, core::Rng& rng);

// An endless, reproducible sequence of worlds: world i is make_clutter_world with
// core::Rng(core::derive_seed(seed, i)), so it depends on nothing but the seed, i and the settings
// at the time it is drawn (not on the worlds before it, nor on how many of them were redrawn).
class ClutterWorldSequence {
 public:
  // Throws ParameterError for invalid settings.
  ClutterWorldSequence(std::uint64_t seed, ClutterWorldSettings settings);

  // World index(), then index() + 1.
  ClutterWorld next();
  // World i at the current settings, without moving the sequence or counting its rejections.
  ClutterWorld at(int i) const;
  // Continue from world i (i >= 0).
  void seek(int i);
  // A new clutter from the next world on (the paper's sudden change of environment). Throws
  // ParameterError outside (0, 1), leaving the settings unchanged.
  void set_clutter(double clutter);

  int index() const { return index_; }
  int rejected_total() const { return rejected_total_; }
  const ClutterWorldSettings& settings() const { return settings_; }

 private:
  std::uint64_t seed_;
  ClutterWorldSettings settings_;
  int index_ = 0;
  int rejected_total_ = 0;
};

}  // namespace amp::nav
