#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "amp/nav/nav_task.hpp"
#include "amp/nav/reference_grid.hpp"

namespace amp::learn {
class Pgcs;
}

namespace amp::nav {

// The grids a PGCS session measures itself against (ReferenceGrid: the cells free for the robot's
// disc): the base world's, for the coverage and quantisation error of the clusters, and the grid of
// the world at a given simulator step, for what the robot can reach by then (query pairs,
// grid-shortest lengths, the prior of clusters a closed door cut off).
class ReferenceWorlds {
 public:
  // `cell`: m, the grids' cell (0: the base world's longer side / 256).
  ReferenceWorlds(const NavTask& task, double cell);

  const ReferenceGrid& base() const { return base_; }
  // Whether any free cell of the base grid is reachable from the task's start.
  bool start_has_room() const;
  // The share of the reachable free cells within 2 sigma of a centre.
  double coverage(const learn::Pgcs& clusters) const;
  // The RMS distance from the reachable free cells (an even subsample) to their nearest centre.
  double quantisation_error(const learn::Pgcs& clusters) const;

  // The free cells reachable from the task's start in the world at simulator step `step` (the grid
  // is made afresh when the world's version changed); now() is that world's grid.
  const std::vector<std::uint8_t>& reachable_at(std::size_t step);
  ReferenceGrid& now() { return *now_; }
  // The prior of the clusters the robot could reach in the base world but no longer can at `step`.
  double closed_prior(const learn::Pgcs& clusters, std::size_t step);

 private:
  std::shared_ptr<const WorldTimeline> timeline_;
  double radius_;
  Eigen::Vector2d start_;
  ReferenceGrid base_;
  std::vector<std::uint8_t> base_reachable_;
  std::unique_ptr<ReferenceGrid> now_;
  std::size_t now_version_ = static_cast<std::size_t>(-1);
  std::vector<std::uint8_t> now_reachable_;
};

}  // namespace amp::nav
