#pragma once
// Private: the FCL geometry of an ArmRobot's links.
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "amp/world/arm_kinematics.hpp"
#include "world/spatial/fcl_scene.hpp"

namespace amp::world::detail {

// One collision solid of one link: its FCL geometry (shared by every checker's object) and pose in
// the link frame.
struct ArmPart {
  int link = 0;
  FclGeometry geometry;
  // A convex shape containing the solid (the mesh's convex hull; a primitive itself): tests against
  // it first, and the exact geometry only when it touches (arm_checker.cpp).
  FclGeometry hull;
  Eigen::Isometry3d local = Eigen::Isometry3d::Identity();
  // A sphere containing the solid, in the link frame: a cheap lower bound on distances.
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double radius = 0.0;
  // The farthest point of the solid from the link frame's origin (solid_reach).
  double reach = 0.0;
};

// How far a joint's own motion can move its child frame's origin from where the joint's origin
// puts it: a slide's travel, nothing for a rotation (the axis passes through the origin).
inline double joint_travel(const ArmJoint& j) {
  return j.type == ArmJointType::kPrismatic ? std::max(std::abs(j.lower), std::abs(j.upper)) : 0.0;
}

struct ArmGeometry {
  std::vector<ArmPart> parts;
};

// What one joint step can do to each thing the checker measures (docs/arms.md, "Certification"):
// for each part, how far its points move in the world per unit step of each group joint, and for
// each self pair, how far the two parts move relative to each other. A constraint c moves at most
// sum_k coefficient(c, k) |dq_k| for joint steps dq, which certification weighs against c's own
// distance instead of the whole robot's worst case.
struct ArmMotionCoefficients {
  int joints = 0;             // group joints: the row length
  std::vector<double> part;   // parts() x joints, row per geometry part
  std::vector<double> pair;   // self part pairs x joints, row per ArmRobot::self_part_pairs() entry
  std::vector<char> part_moves, pair_moves;  // a row that is not all zero: some group joint moves it

  // sum_k row(k) * step[k]
  static double dot(const double* row, const double* step, int n) {
    double v = 0.0;
    for (int k = 0; k < n; ++k) v += row[k] * step[k];
    return v;
  }
};

ArmMotionCoefficients arm_motion_coefficients(const ArmKinematics& kinematics, const ArmGeometry& geometry,
                                              const std::vector<std::pair<int, int>>& part_pairs);

// Each group joint's travel from a to b along the space's interpolation, into steps[0..dof): |b - a|,
// the shorter way round for a continuous joint. What the motion coefficients multiply.
void arm_joint_steps(const ArmKinematics& kinematics, const State& a, const State& b, double* steps);

}  // namespace amp::world::detail
