#pragma once
#include <Eigen/Geometry>

#include "amp/core/space.hpp"

namespace amp::core {

// SE3: position in a box and a unit quaternion; State = (x, y, z, qx, qy, qz, qw).
// distance = translation_weight * |p_a - p_b| + rotation_weight * angle(q_a, q_b), where angle is the
// rotation angle between the two orientations in [0, pi]; interpolation is lerp + slerp.
class Se3Space final : public Space {
 public:
  Se3Space(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, double rotation_weight,
           double translation_weight = 1.0, double resolution_fraction = 0.01);

  std::string_view kind() const override { return "se3"; }
  int dimension() const override { return 7; }
  int dof() const override { return 6; }
  int unit_dimension() const override { return 6; }
  void from_unit(const double* u, State& out) const override;
  double distance(const State& a, const State& b) const override;
  void interpolate(const State& a, const State& b, double t, State& out) const override;
  bool in_bounds(const State& s) const override;
  void enforce_bounds(State& s) const override;
  double maximum_extent() const override;
  int embedding_dimension() const override { return 7; }
  void embed(const State& s, double* out) const override { embed_variant(s, 0, out); }
  int embedding_variants() const override { return 2; }
  void embed_variant(const State& s, int variant, double* out) const override;
  // The position's three lines (weight translation_weight), then the quaternion.
  std::optional<CoordinateLayout> coordinate_layout() const override;

  const Eigen::Vector3d& lo() const { return lo_; }
  double translation_weight() const { return translation_weight_; }
  double rotation_weight() const { return rotation_weight_; }
  const Eigen::Vector3d& hi() const { return hi_; }
  static Eigen::Quaterniond rotation(const State& s) { return Eigen::Quaterniond(s[6], s[3], s[4], s[5]); }
  static State make_state(const Eigen::Vector3d& p, const Eigen::Quaterniond& q);

 private:
  Eigen::Vector3d lo_, hi_;
  double rotation_weight_;
  double translation_weight_;
};

}  // namespace amp::core
