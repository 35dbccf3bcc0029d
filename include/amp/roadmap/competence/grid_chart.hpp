#pragma once
#include <vector>

#include <Eigen/Geometry>

#include "amp/core/space.hpp"
#include "amp/core/state.hpp"

namespace amp::roadmap {

// Flat coordinates around an origin state, for searching a C-space on a grid (the A* local
// planner of Isto 2003, docs/run-cost-variance.md). One coordinate per degree of freedom, read
// from the space's core::CoordinateLayout:
//   lines and angles (JointSpace: Rn, SE2, linkages, SCARA): offsets from the origin (angles the
//     short way round); grid step (hi - lo) / steps, 2 pi / steps for angles;
//   a 3-D position and a quaternion (Se3Space): translation offset, then the rotation vector of
//     q_origin^-1 q (the exponential chart at the origin, valid everywhere, so a search may wander
//     past pi); translation step (hi - lo) / steps per axis, rotation step 2 pi / steps.
class GridChart {
 public:
  // Throws ParameterError for steps < 1 and for a space with no such layout (UnicycleSpace).
  GridChart(const core::Space& space, int steps);

  int dimension() const { return static_cast<int>(step_.size()); }
  double step(int i) const { return step_[static_cast<std::size_t>(i)]; }

  void set_origin(const State& origin);
  // The chart coordinates of s (relative to the origin) into x[0..dimension()).
  void coordinates(const State& s, double* x) const;
  // The state at chart coordinates x; false when it lies outside the space's bounds.
  bool state_at(const double* x, State& out) const;

 private:
  enum class Axis { kLinear, kAngle, kTranslation, kRotation };
  std::vector<Axis> axis_;
  std::vector<double> step_, lo_, hi_;
  State origin_;
  Eigen::Quaterniond origin_rotation_ = Eigen::Quaterniond::Identity();
};

}  // namespace amp::roadmap
