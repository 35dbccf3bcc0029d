#include "amp/world/arm_kinematics.hpp"

#include <cmath>

#include "amp/core/error.hpp"

namespace amp::world {

Eigen::Isometry3d joint_motion(const ArmJoint& j, double v) {
  Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
  switch (j.type) {
    case ArmJointType::kRevolute:
    case ArmJointType::kContinuous:
      m.linear() = Eigen::AngleAxisd(v, j.axis).toRotationMatrix();
      break;
    case ArmJointType::kPrismatic:
      m.translation() = v * j.axis;
      break;
    case ArmJointType::kFixed:
      break;
  }
  return m;
}

ArmKinematics::ArmKinematics(std::shared_ptr<const ArmModel> model, PlanningGroup group, std::vector<double> held)
    : model_(std::move(model)), group_(std::move(group)), held_(std::move(held)) {
  const std::size_t n = model_->joints().size();
  if (held_.size() != n) throw ParameterError("arm kinematics: a held value is needed for every joint");
  state_index_.assign(n, -1);
  for (std::size_t k = 0; k < group_.joints.size(); ++k) state_index_[static_cast<std::size_t>(group_.joints[k])] = static_cast<int>(k);
  for (std::size_t j = 0; j < n; ++j) {  // a mimic chain longer than the joint count loops
    int at = static_cast<int>(j);
    for (std::size_t steps = 0; model_->joint(at).mimic_joint >= 0; ++steps) {
      if (steps > n) throw ParameterError("arm kinematics: joint '" + model_->joint(static_cast<int>(j)).name + "': mimic joints form a cycle");
      at = model_->joint(at).mimic_joint;
    }
  }
}

double ArmKinematics::joint_value(const State& q, int j) const {
  const ArmJoint& joint = model_->joint(j);
  if (!joint.movable()) return 0.0;
  if (joint.mimic_joint >= 0) return joint.mimic_multiplier * joint_value(q, joint.mimic_joint) + joint.mimic_offset;
  const int k = state_index_[static_cast<std::size_t>(j)];
  return k >= 0 ? q[k] : held_[static_cast<std::size_t>(j)];
}

void ArmKinematics::link_poses(const State& q, Eigen::Isometry3d* out) const {
  out[0] = Eigen::Isometry3d::Identity();
  const auto& joints = model_->joints();
  // Joints are numbered depth-first, so a joint's parent link is posed before it.
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const ArmJoint& joint = joints[j];
    Eigen::Isometry3d& child = out[joint.child_link];
    child = out[joint.parent_link] * joint.origin;
    if (!joint.movable()) continue;
    const double v = joint_value(q, static_cast<int>(j));
    if (joint.type != ArmJointType::kPrismatic && joint.axis == Eigen::Vector3d::UnitZ()) {
      // A turn about z (most URDFs' convention) mixes two columns: a quarter of the general product.
      const double c = std::cos(v), s = std::sin(v);
      const Eigen::Vector3d x = child.linear().col(0), y = child.linear().col(1);
      child.linear().col(0) = c * x + s * y;
      child.linear().col(1) = c * y - s * x;
    } else {
      child = child * joint_motion(joint, v);
    }
  }
}

Eigen::Vector3d ArmKinematics::tip_position(const State& q) const {
  // Only the chain from the root to the tip matters.
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  for (int l = group_.tip_link; model_->link(l).parent_joint >= 0;) {
    const int j = model_->link(l).parent_joint;
    const ArmJoint& joint = model_->joint(j);
    pose = joint.origin * (joint.movable() ? joint_motion(joint, joint_value(q, j)) : Eigen::Isometry3d::Identity()) * pose;
    l = joint.parent_link;
  }
  return pose.translation();
}

}  // namespace amp::world
