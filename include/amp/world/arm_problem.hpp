#pragma once
// A MoveIt user's problem, from their own files: URDF + SRDF + PlanningScene + MotionPlanRequest
// (`amp plan --urdf R.urdf --srdf R.srdf --scene S.yaml --request Q.yaml`, or a problem file
// naming the four: docs/problem-format.md, "Arms").
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "amp/world/arm_srdf.hpp"
#include "amp/world/problem.hpp"

namespace amp::world {

namespace detail {
struct ArmGeometry;
}

struct ArmFiles {
  std::filesystem::path urdf, srdf, scene, request;
  std::vector<std::filesystem::path> package_paths;  // for package:// URIs beyond the URDF's folder
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
  std::shared_ptr<const ArmModel> model;
  Srdf srdf_content;
  std::shared_ptr<const detail::ArmGeometry> geometry;
};
ArmDescription load_arm_description(const std::filesystem::path& urdf, const std::filesystem::path& srdf,
                                    const std::vector<std::filesystem::path>& package_paths = {});
// load_arm_problem on a robot already read.
Problem load_arm_problem(const ArmDescription& robot, const std::filesystem::path& scene,
                         const std::filesystem::path& request);

}  // namespace amp::world
