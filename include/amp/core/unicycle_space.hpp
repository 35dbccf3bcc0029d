#pragma once
#include "amp/core/space.hpp"

namespace amp::core {

// Box of a UnicycleSpace. Every bound must be given (designated initialisers read best); an omitted
// pair is 0, 0 and rejected. A symmetric turn-rate limit is omega_min = -omega_max.
struct UnicycleBounds {
  double x_min = 0.0, x_max = 0.0;
  double y_min = 0.0, y_max = 0.0;
  double v_min = 0.0, v_max = 0.0;          // forward speed, length / s (v_min < 0 allows reversing)
  double omega_min = 0.0, omega_max = 0.0;  // turn rate, rad / s
};

// Metric weights: each converts its coordinate's difference into length.
struct UnicycleWeights {
  double theta = 1.0;  // length per radian (OMPL's SE2 weight 1; use the robot's radius for a disc)
  double v = 1.0;      // seconds: a time scale turning a speed difference into a distance
  double omega = 1.0;  // length * s / rad: a time scale times a turning radius
};

// The full state of a mobile robot with unicycle kinematics, State = (x, y, theta, v, omega): a
// position in a box, a heading on SO(2) wrapped into (-pi, pi], and the velocity command it is
// executing (forward speed v in [v_min, v_max], turn rate omega in [omega_min, omega_max]).
// distance = sqrt(dx^2 + dy^2 + (w_theta * dtheta)^2 + (w_v * dv)^2 + (w_omega * domega)^2), where
// dtheta is the shortest signed angle between the headings: an l2 product of metrics, so a metric.
// Interpolation is linear in x, y, v, omega and along the shorter arc in theta.
// (JointSpace's continuous joints wrap into [-pi, pi); here pi itself is the representative.)
class UnicycleSpace final : public Space {
 public:
  static constexpr int kX = 0, kY = 1, kTheta = 2, kV = 3, kOmega = 4;

  // Throws ParameterError (naming the field) for a bound that is not finite, min >= max, a weight
  // that is not positive and finite, or a resolution fraction outside (0, 1]. The resolution is
  // resolution_fraction * maximum_extent(), as for the other spaces.
  explicit UnicycleSpace(const UnicycleBounds& bounds, const UnicycleWeights& weights = {},
                         double resolution_fraction = 0.01);

  std::string_view kind() const override { return "unicycle"; }
  int dimension() const override { return 5; }
  void from_unit(const double* u, State& out) const override;
  double distance(const State& a, const State& b) const override;
  // t = 0 gives a and t = 1 gives b exactly (heading wrapped into (-pi, pi]).
  void interpolate(const State& a, const State& b, double t, State& out) const override;
  // Five finite coordinates with x, y, v, omega inside the box; any finite heading names an angle.
  bool in_bounds(const State& s) const override;
  // Clamps x, y, v, omega to the box and wraps theta into (-pi, pi].
  void enforce_bounds(State& s) const override;
  double maximum_extent() const override { return extent_; }
  // (x, y, w_theta cos theta, w_theta sin theta, w_v v, w_omega omega): the chord never exceeds
  // the arc, so the embedding's Euclidean distance is a lower bound of distance().
  int embedding_dimension() const override { return 6; }
  void embed(const State& s, double* out) const override;

  const UnicycleBounds& bounds() const { return bounds_; }
  const UnicycleWeights& weights() const { return weights_; }

  static State make_state(double x, double y, double theta, double v, double omega);
  // theta wrapped into (-pi, pi]; values already there are returned unchanged (bit for bit).
  static double wrap_heading(double theta);
  // Shortest signed angle from a to b, in (-pi, pi] (antipodal headings turn counter-clockwise).
  static double heading_difference(double a, double b);

 private:
  UnicycleBounds bounds_;
  UnicycleWeights weights_;
  double extent_ = 0.0;
};

}  // namespace amp::core
