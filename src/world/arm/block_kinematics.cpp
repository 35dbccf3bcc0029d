#include "world/arm/block_kinematics.hpp"

#include <algorithm>
#include <cmath>

namespace amp::world::detail {

void pose_values(const Eigen::Isometry3d& m, double* out) {
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) out[row * 3 + col] = m.linear()(row, col);
    out[9 + row] = m.translation()[row];
  }
}

namespace {

// One pose in every lane of a block.
void broadcast(const double* pose, double* block) {
  for (std::size_t e = 0; e < 12; ++e) std::fill_n(block + e * kSphereLanes, kSphereLanes, pose[e]);
}

}  // namespace

BlockKinematics::BlockKinematics(const ArmKinematics& kinematics, const SphereKernels& kernels)
    : kinematics_(&kinematics), kernels_(&kernels), rhs_(kPoseBlock) {
  const auto& joints = kinematics.model().joints();
  fixed_.resize(joints.size() * 12);
  fixed_block_.resize(joints.size() * kPoseBlock);
  turns_z_.resize(joints.size());
  for (std::size_t j = 0; j < joints.size(); ++j) {
    pose_values(joints[j].origin, &fixed_[j * 12]);
    broadcast(&fixed_[j * 12], &fixed_block_[j * kPoseBlock]);
    turns_z_[j] = joints[j].type != ArmJointType::kPrismatic && joints[j].movable() && joints[j].axis == Eigen::Vector3d::UnitZ();
  }
}

void BlockKinematics::poses(const State* const* q, std::size_t n, double* out) const {
  static constexpr double kIdentity[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};
  broadcast(kIdentity, out);
  const auto& joints = kinematics_->model().joints();
  double* rhs = rhs_.data();
  // Joints are numbered depth-first, so a joint's parent link is posed before it.
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const ArmJoint& joint = joints[j];
    const double* parent = out + static_cast<std::size_t>(joint.parent_link) * kPoseBlock;
    double* child = out + static_cast<std::size_t>(joint.child_link) * kPoseBlock;
    if (!joint.movable()) {
      kernels_->compose(parent, &fixed_block_[j * kPoseBlock], child);
      continue;
    }
    // Lanes from n on repeat lane n - 1: their values (and sines) are copied, not recomputed.
    double values[kSphereLanes];
    for (std::size_t k = 0; k < n; ++k) values[k] = kinematics_->joint_value(*q[k], static_cast<int>(j));
    std::fill(values + n, values + kSphereLanes, values[n - 1]);
    if (turns_z_[j] != 0) {
      double c[kSphereLanes], s[kSphereLanes];
      for (std::size_t k = 0; k < n; ++k) c[k] = std::cos(values[k]), s[k] = std::sin(values[k]);
      std::fill(c + n, c + kSphereLanes, c[n - 1]);
      std::fill(s + n, s + kSphereLanes, s[n - 1]);
      kernels_->turn_z(&fixed_[j * 12], c, s, rhs);
    } else {
      // Other axes and slides: the lane's whole joint transform, scalar.
      for (std::size_t k = 0; k < kSphereLanes; ++k) {
        double m[12];
        pose_values(joint.origin * joint_motion(joint, values[k]), m);
        for (std::size_t e = 0; e < 12; ++e) rhs[e * kSphereLanes + k] = m[e];
      }
    }
    kernels_->compose(parent, rhs, child);
  }
}

}  // namespace amp::world::detail
