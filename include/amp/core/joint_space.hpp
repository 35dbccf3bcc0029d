#pragma once
#include <string>
#include <vector>

#include "amp/core/space.hpp"

namespace amp::core {

// How one coordinate of a JointSpace behaves.
enum class JointKind {
  kLinear,      // a translation or slide, clamped to [lo, hi]
  kRevolute,    // an angle with joint limits [lo, hi], |hi - lo| <= 2pi, never wraps
  kContinuous,  // an angle that wraps around: distance the shortest way round, lo/hi ignored
};

struct Joint {
  std::string name;
  JointKind kind = JointKind::kLinear;
  double lo = 0.0;
  double hi = 1.0;
  double weight = 1.0;  // metric weight: distance = sqrt(sum (weight_i * d_i)^2)
};

// A product of lines and circles with a weighted Euclidean metric. Rn, SE2 and every linkage are
// JointSpaces; they differ only in their joints and kind().
class JointSpace final : public Space {
 public:
  // Throws ParameterError for an empty joint list, lo >= hi, a revolute range over 2pi, weight <= 0.
  JointSpace(std::string kind, std::vector<Joint> joints, double resolution_fraction = 0.01);

  std::string_view kind() const override { return kind_; }
  int dimension() const override { return static_cast<int>(joints_.size()); }
  void from_unit(const double* u, State& out) const override;
  double distance(const State& a, const State& b) const override;
  void interpolate(const State& a, const State& b, double t, State& out) const override;
  bool in_bounds(const State& s) const override;
  void enforce_bounds(State& s) const override;
  double maximum_extent() const override { return extent_; }
  int embedding_dimension() const override { return embedding_dim_; }
  void embed(const State& s, double* out) const override;
  // One axis per joint: continuous joints are angles; linear and revolute ones are lines.
  std::optional<CoordinateLayout> coordinate_layout() const override;

  const std::vector<Joint>& joints() const { return joints_; }

 private:
  std::string kind_;
  std::vector<Joint> joints_;
  int embedding_dim_ = 0;
  double extent_ = 0.0;
};

// Signed shortest angular difference b - a, in [-pi, pi).
double angle_difference(double a, double b);
// Wraps an angle into [-pi, pi).
double wrap_angle(double a);

// Rn in bounds [lo, hi] (n = lo.size()).
JointSpace make_rn_space(const std::vector<double>& lo, const std::vector<double>& hi);
// SE2 (x, y, theta); rotation_weight converts radians to length (use the robot's radius).
JointSpace make_se2_space(double xlo, double ylo, double xhi, double yhi, double rotation_weight);

}  // namespace amp::core
