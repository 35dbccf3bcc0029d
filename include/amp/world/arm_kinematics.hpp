#pragma once
// Forward kinematics of an ArmModel for one planning group: the group's joints come from the state,
// every other movable joint is held at a fixed value (the request's start state), mimic joints
// follow their leaders. Checked against KDL in tests/world/arm/arm_kinematics_test.cpp.
#include <memory>
#include <vector>

#include <Eigen/Geometry>

#include "amp/core/state.hpp"
#include "amp/world/arm_model.hpp"
#include "amp/world/arm_srdf.hpp"

namespace amp::world {

class ArmKinematics {
 public:
  // `held` gives a value for every model joint (indexed as model.joints()); the group's entries
  // are overwritten by each state. Throws ParameterError when sizes disagree or mimic joints form
  // a cycle.
  ArmKinematics(std::shared_ptr<const ArmModel> model, PlanningGroup group, std::vector<double> held);

  const ArmModel& model() const { return *model_; }
  const PlanningGroup& group() const { return group_; }
  int dof() const { return static_cast<int>(group_.joints.size()); }
  std::size_t link_count() const { return model_->links().size(); }

  // The world pose of every link (`out` holds link_count() poses; the root at the identity).
  // Allocates nothing.
  void link_poses(const State& q, Eigen::Isometry3d* out) const;
  // The value of model joint j at state q (mimic applied; fixed joints 0).
  double joint_value(const State& q, int j) const;
  // The group's reference point: the tip link's origin.
  Eigen::Vector3d tip_position(const State& q) const;

 private:
  std::shared_ptr<const ArmModel> model_;
  PlanningGroup group_;
  std::vector<double> held_;
  std::vector<int> state_index_;  // per model joint: its coordinate in the state, or -1
};

// The motion of joint `j` at value v, in the child frame: a rotation about the axis or a slide along it.
Eigen::Isometry3d joint_motion(const ArmJoint& j, double v);

}  // namespace amp::world
