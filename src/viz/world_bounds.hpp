#pragma once
#include <Eigen/Geometry>

#include "amp/world/problem.hpp"

namespace amp::viz {

// The workspace seen from above: the figures of a 2-D world (PGCS, policy search) draw its panels
// over this box.
inline Eigen::AlignedBox2d bounds_2d(const world::Problem& problem) {
  const Eigen::AlignedBox3d b = problem.environment->workspace_bounds();
  return {b.min().head<2>(), b.max().head<2>()};
}

}  // namespace amp::viz
