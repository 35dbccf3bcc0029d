#pragma once
// A MoveIt user's problem, from their own files: URDF + SRDF + PlanningScene + MotionPlanRequest
// (`amp plan --urdf R.urdf --srdf R.srdf --scene S.yaml --request Q.yaml`, or a problem file
// naming the four: docs/problem-format.md, "Arms").
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "amp/world/arm_spheres.hpp"
#include "amp/world/arm_srdf.hpp"
#include "amp/world/problem.hpp"

namespace amp::world {

namespace detail {
struct ArmGeometry;
}

// Which geometry collision checking uses (docs/arms.md, "Sphere model"): the URDF's collision
// solids through FCL (the default), or spheres covering them through the sphere checker.
enum class ArmCollision { kMeshes, kSpheres };

// Reads "meshes" or "spheres"; throws ParameterError naming `where` otherwise.
ArmCollision parse_arm_collision(const std::string& text, const std::string& where);

// How the robot's collision geometry is made.
struct ArmCollisionOptions {
  ArmCollision model = ArmCollision::kMeshes;
  // With kSpheres: a spherized URDF whose spheres are grown to cover the solids; empty: spheres
  // generated from the solids (through `cache_dir`, when not empty).
  std::filesystem::path spheres;
  std::filesystem::path cache_dir;
};

struct ArmFiles {
  std::filesystem::path urdf, srdf, scene, request;
  std::vector<std::filesystem::path> package_paths;  // for package:// URIs beyond the URDF's folder
  ArmCollisionOptions collision;
};

// The request's group as a JointSpace ("arm": the group's joints in the model's order, hard
// limits, continuous joints wrapping; resolution 0.005 of the extent, MoveIt's default
// longest_valid_segment_fraction), the scene's objects, the start (scene state, then the request's
// start state) and the joint goal. Joints outside the group keep their start values; names that
// are not movable joints of the group (fixed joints, the virtual joint) are ignored. The default
// planner is rrt-connect (MoveIt's), the time limit the request's allowed_planning_time.
// Throws FileError naming the file and the field: any reader's error, a goal joint not in the
// group or a group joint without a goal or a start value, a value outside the joint's limits, a
// start or goal in collision (naming the two links, or the link and the object).
Problem load_arm_problem(const ArmFiles& files);

// A robot read once for many problems (a folder of MotionBenchMaker scenes): its model, SRDF and
// collision geometry.
struct ArmDescription {
  std::filesystem::path urdf, srdf;
  // The model planned with: the URDF's, or its sphere model (collision: spheres).
  std::shared_ptr<const ArmModel> model;
  // With spheres: the URDF's own model (the exact geometry) and how the spheres cover it.
  std::shared_ptr<const ArmModel> exact_model;
  std::shared_ptr<const detail::ArmGeometry> exact_geometry;
  std::vector<LinkCoverReport> cover;
  Srdf srdf_content;
  std::shared_ptr<const detail::ArmGeometry> geometry;
};
ArmDescription load_arm_description(const std::filesystem::path& urdf, const std::filesystem::path& srdf,
                                    const std::vector<std::filesystem::path>& package_paths = {},
                                    const ArmCollisionOptions& collision = {});
// load_arm_problem on a robot already read.
Problem load_arm_problem(const ArmDescription& robot, const std::filesystem::path& scene,
                         const std::filesystem::path& request);

}  // namespace amp::world
