#pragma once
// A robot arm as a URDF describes it: a tree of links joined by joints, each link with its collision
// solids. Read with urdfdom (load_urdf); the SRDF (arm_srdf.hpp) picks the planning group, and
// ArmKinematics (arm_kinematics.hpp) poses the links.
#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "amp/world/spatial_world.hpp"

namespace amp::world {

enum class ArmJointType { kFixed, kRevolute, kContinuous, kPrismatic };

struct ArmJoint {
  std::string name;
  ArmJointType type = ArmJointType::kFixed;
  int parent_link = -1;
  int child_link = -1;
  // The child link's frame in the parent's at joint value 0 (URDF `<origin>`).
  Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();  // unit, in the joint (= child) frame
  // The `<limit>` element's hard bounds (revolute, prismatic); `<safety_controller>` soft limits are
  // not applied, as VAMP does not (two shared MotionBenchMaker goals lie outside them).
  double lower = 0.0;
  double upper = 0.0;
  // `<mimic>`: value = multiplier * value(mimic_joint) + offset; -1 when the joint is its own.
  int mimic_joint = -1;
  double mimic_multiplier = 1.0;
  double mimic_offset = 0.0;

  bool movable() const { return type != ArmJointType::kFixed; }
};

struct ArmLink {
  std::string name;
  int parent_joint = -1;  // -1 for the root link
  std::vector<int> child_joints;
  std::vector<Solid> collision;  // `<collision>` elements, posed in the link frame
};

// The kinematic tree. Link 0 is the root; links and joints are numbered depth-first from it, as
// MoveIt numbers its joint models, so that a parent always precedes its children.
class ArmModel {
 public:
  ArmModel(std::string name, std::vector<ArmLink> links, std::vector<ArmJoint> joints);

  const std::string& name() const { return name_; }
  const std::vector<ArmLink>& links() const { return links_; }
  const std::vector<ArmJoint>& joints() const { return joints_; }
  const ArmLink& link(int i) const { return links_[static_cast<std::size_t>(i)]; }
  const ArmJoint& joint(int i) const { return joints_[static_cast<std::size_t>(i)]; }
  // -1 when absent.
  int link_index(const std::string& name) const;
  int joint_index(const std::string& name) const;
  // Whether link `descendant` lies in the subtree of link `ancestor` (a link is its own descendant).
  bool in_subtree(int ancestor, int descendant) const;

 private:
  std::string name_;
  std::vector<ArmLink> links_;
  std::vector<ArmJoint> joints_;
};

// Where `package://NAME/rest` URIs are looked for, besides the URDF's own folder.
struct UrdfOptions {
  std::vector<std::filesystem::path> package_paths;
};

// Reads a URDF with urdfdom: joints (revolute, continuous, prismatic, fixed; floating and planar are
// refused), limits, mimic, and every link's `<collision>` geometry (meshes through load_mesh, with
// their scale; boxes, cylinders and spheres), with their origins. `<visual>` is ignored.
// `package://NAME/rest` resolves to the first existing of, for each folder F (the URDF's folder,
// then options.package_paths): F/rest, F/NAME/rest. Throws FileError naming the file and the
// element: not a URDF, a missing mesh (with the places tried), an unsupported joint type.
ArmModel load_urdf(const std::filesystem::path& file, const UrdfOptions& options = {});
// The same from text; `label` names it in errors and `base_dir` resolves relative mesh paths.
ArmModel parse_urdf(const std::string& xml, const std::string& label, const std::filesystem::path& base_dir,
                    const UrdfOptions& options = {});

}  // namespace amp::world
