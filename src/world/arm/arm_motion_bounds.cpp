// Per-part and per-pair motion coefficients of an arm (arm_geometry.hpp): the joint-step bounds
// of docs/arms.md, "Certification", taken for each part along its own chain instead of once for
// each joint's whole subtree.
#include <cmath>
#include <vector>

#include "amp/core/joint_space.hpp"
#include "world/arm/arm_geometry.hpp"

namespace amp::world::detail {

namespace {

// For every model joint: the group joint whose value drives it, and the factor (1 for a group
// joint itself, the product of multipliers along a mimic chain), or -1 when no group joint does.
struct Drivers {
  std::vector<int> group_joint;
  std::vector<double> factor;
};

Drivers drivers_of(const ArmKinematics& kin) {
  const ArmModel& m = kin.model();
  const std::size_t n = m.joints().size();
  Drivers d{std::vector<int>(n, -1), std::vector<double>(n, 0.0)};
  std::vector<int> in_group(n, -1);
  const std::vector<int>& group = kin.group().joints;
  for (std::size_t k = 0; k < group.size(); ++k) in_group[static_cast<std::size_t>(group[k])] = static_cast<int>(k);
  for (std::size_t j = 0; j < n; ++j) {
    double factor = 1.0;
    int at = static_cast<int>(j);
    // A mimic chain is at most as long as the joints (ArmKinematics refuses cycles).
    for (std::size_t hops = 0; hops <= n && at >= 0; ++hops) {
      if (in_group[static_cast<std::size_t>(at)] >= 0) {
        d.group_joint[j] = in_group[static_cast<std::size_t>(at)];
        d.factor[j] = std::abs(factor);
        break;
      }
      const ArmJoint& joint = m.joint(at);
      factor *= joint.mimic_multiplier;
      at = joint.mimic_joint;
    }
  }
  return d;
}

// Adds to `row` what the joints between link `from` and its ancestor `until` (exclusive; -1: the
// root) do to a part of `from` whose points lie within `reach` of from's frame origin: a rotation
// moves them at most their distance from its axis (bounded by the distance from its child frame's
// origin, accumulated upward), a slide by its own step.
void add_chain(const ArmModel& m, const Drivers& d, int from, int until, double reach, double* row) {
  double distance = reach;
  for (int link = from; link != until;) {
    const int j = m.link(link).parent_joint;
    if (j < 0) break;
    const ArmJoint& joint = m.joint(j);
    const int k = d.group_joint[static_cast<std::size_t>(j)];
    if (k >= 0) row[k] += d.factor[static_cast<std::size_t>(j)] * (joint.type == ArmJointType::kPrismatic ? 1.0 : distance);
    distance += joint.origin.translation().norm() + joint_travel(joint);
    link = joint.parent_link;
  }
}

// The deepest link that is an ancestor of (or equal to) both a and b.
int common_ancestor(const ArmModel& m, int a, int b) {
  std::vector<char> above_a(m.links().size(), 0);
  for (int l = a; l >= 0;) {
    above_a[static_cast<std::size_t>(l)] = 1;
    const int j = m.link(l).parent_joint;
    l = j < 0 ? -1 : m.joint(j).parent_link;
  }
  for (int l = b; l >= 0;) {
    if (above_a[static_cast<std::size_t>(l)] != 0) return l;
    const int j = m.link(l).parent_joint;
    l = j < 0 ? -1 : m.joint(j).parent_link;
  }
  return -1;
}

bool any_nonzero(const double* row, int n) {
  for (int k = 0; k < n; ++k) {
    if (row[k] != 0.0) return true;
  }
  return false;
}

}  // namespace

ArmMotionCoefficients arm_motion_coefficients(const ArmKinematics& kinematics, const ArmGeometry& geometry,
                                              const std::vector<std::pair<int, int>>& part_pairs) {
  const ArmModel& m = kinematics.model();
  const Drivers d = drivers_of(kinematics);
  ArmMotionCoefficients c;
  c.joints = kinematics.dof();
  const auto n = static_cast<std::size_t>(c.joints);
  c.part.assign(geometry.parts.size() * n, 0.0);
  for (std::size_t p = 0; p < geometry.parts.size(); ++p) {
    const ArmPart& part = geometry.parts[p];
    add_chain(m, d, part.link, -1, part.reach, &c.part[p * n]);
    c.part_moves.push_back(any_nonzero(&c.part[p * n], c.joints) ? 1 : 0);
  }
  // Two parts move relative to each other only by the joints between them and their common
  // ancestor: what moves both alike does not change their distance.
  c.pair.assign(part_pairs.size() * n, 0.0);
  for (std::size_t i = 0; i < part_pairs.size(); ++i) {
    const ArmPart& a = geometry.parts[static_cast<std::size_t>(part_pairs[i].first)];
    const ArmPart& b = geometry.parts[static_cast<std::size_t>(part_pairs[i].second)];
    const int top = common_ancestor(m, a.link, b.link);
    add_chain(m, d, a.link, top, a.reach, &c.pair[i * n]);
    add_chain(m, d, b.link, top, b.reach, &c.pair[i * n]);
    c.pair_moves.push_back(any_nonzero(&c.pair[i * n], c.joints) ? 1 : 0);
  }
  return c;
}

void arm_joint_steps(const ArmKinematics& kinematics, const State& a, const State& b, double* steps) {
  const ArmModel& m = kinematics.model();
  const std::vector<int>& joints = kinematics.group().joints;
  for (std::size_t k = 0; k < joints.size(); ++k) {
    const int i = static_cast<int>(k);
    steps[k] = m.joint(joints[k]).type == ArmJointType::kContinuous ? std::abs(core::angle_difference(a[i], b[i]))
                                                                    : std::abs(b[i] - a[i]);
  }
}

}  // namespace amp::world::detail
