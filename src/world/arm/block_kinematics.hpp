#pragma once
// Private: the forward kinematics of a block of configurations at once, for the sphere checker
// (sphere_checker.cpp). Every link's pose in kSphereLanes configurations is a pose block
// (sphere_kernels.hpp), composed lane by lane by the SIMD kernels, as VAMP poses its robots:
// the joint values, their sines and cosines and any joint other than a turn about z are scalar per
// lane, the products of the chain vectorised. Lanes are independent and the kernels contract no
// products, so a configuration's poses do not depend on its lane or on the others in its block.
#include <cstddef>
#include <vector>

#include "amp/world/arm_kinematics.hpp"
#include "world/arm/sphere_kernels.hpp"

namespace amp::world::detail {

class BlockKinematics {
 public:
  BlockKinematics(const ArmKinematics& kinematics, const SphereKernels& kernels);

  std::size_t link_count() const { return kinematics_->link_count(); }
  // The pose blocks of every link (out holds link_count() * kPoseBlock values; link l's block at
  // l * kPoseBlock) for states q[0..n), 1 <= n <= kSphereLanes; lanes from n on repeat q[n - 1].
  // Allocates nothing.
  void poses(const State* const* q, std::size_t n, double* out) const;

 private:
  const ArmKinematics* kinematics_;
  const SphereKernels* kernels_;
  std::vector<double> fixed_;  // per joint: its origin as 12 values (kernels' pose layout)
  std::vector<double> fixed_block_;  // per joint: its origin in every lane (a pose block)
  std::vector<char> turns_z_;        // per joint: a revolute or continuous turn about z
  mutable std::vector<double> rhs_;  // one pose block of scratch
};

// An isometry as the kernels' 12 values: the rotation row-major, then the translation.
void pose_values(const Eigen::Isometry3d& m, double* out);

}  // namespace amp::world::detail
