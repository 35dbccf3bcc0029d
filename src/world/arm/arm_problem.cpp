#include "amp/world/arm_problem.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include "amp/core/error.hpp"
#include "amp/core/joint_space.hpp"
#include "amp/core/number_text.hpp"
#include "amp/world/arm_environment.hpp"
#include "amp/world/arm_srdf.hpp"
#include "amp/world/moveit_files.hpp"

namespace amp::world {

namespace {

namespace fs = std::filesystem;

// MoveIt's default longest_valid_segment_fraction: the discrete edge check's step.
constexpr double kMoveItResolution = 0.005;

core::JointKind joint_kind(ArmJointType t) {
  switch (t) {
    case ArmJointType::kContinuous: return core::JointKind::kContinuous;
    case ArmJointType::kPrismatic: return core::JointKind::kLinear;
    default: return core::JointKind::kRevolute;
  }
}

std::shared_ptr<const core::JointSpace> group_space(const ArmModel& m, const PlanningGroup& g, const ArmFiles& files) {
  std::vector<core::Joint> joints;
  for (const int j : g.joints) {
    const ArmJoint& a = m.joint(j);
    core::Joint out{a.name, joint_kind(a.type), a.lower, a.upper, 1.0};
    if (a.type == ArmJointType::kContinuous) out.lo = -std::numbers::pi, out.hi = std::numbers::pi;
    // A revolute joint with more than a turn between its limits (UR arms: +-2 pi) does not wrap
    // either: its angle is a bounded line.
    if (a.type == ArmJointType::kRevolute && a.upper - a.lower > 2.0 * std::numbers::pi) out.kind = core::JointKind::kLinear;
    if (!(a.upper > a.lower) && a.type != ArmJointType::kContinuous) {
      throw FileError(files.urdf.string() + ": joint '" + a.name + "': limit: lower must be below upper for a joint to plan");
    }
    joints.push_back(out);
  }
  return std::make_shared<core::JointSpace>("arm", std::move(joints), kMoveItResolution);
}

void check_group_exists(const Srdf& srdf, const std::string& group, const ArmFiles& files) {
  for (const SrdfGroup& g : srdf.groups) {
    if (g.name == group) return;
  }
  std::string names;
  for (const SrdfGroup& g : srdf.groups) names += (names.empty() ? "" : ", ") + g.name;
  throw FileError(files.request.string() + ": group_name: no group '" + group + "' in " + files.srdf.string() +
                  " (groups: " + (names.empty() ? "none" : names) + ")");
}

// Every model joint's value at the start: 0, then the scene's robot state, then the request's.
std::vector<double> start_values(const ArmModel& m, const MoveItScene& scene, const MoveItRequest& request) {
  std::vector<double> v(m.joints().size(), 0.0);
  for (const JointValues* source : {&scene.robot_state, &request.start}) {
    for (const auto& [name, value] : *source) {
      const int j = m.joint_index(name);
      if (j >= 0 && m.joint(j).movable()) v[static_cast<std::size_t>(j)] = value;
    }
  }
  return v;
}

void check_limits(const ArmJoint& j, double v, const std::string& where) {
  if (!std::isfinite(v)) throw FileError(where + ": joint '" + j.name + "': the value is not a finite number");
  if (j.type == ArmJointType::kContinuous) return;
  if (v < j.lower || v > j.upper) {
    throw FileError(where + ": joint '" + j.name + "': " + core::number_text(v) + " is outside its limits [" + core::number_text(j.lower) + ", " +
                    core::number_text(j.upper) + "]");
  }
}

State start_state(const ArmModel& m, const PlanningGroup& g, const MoveItScene& scene, const MoveItRequest& request,
                  const ArmFiles& files) {
  State s(static_cast<int>(g.joints.size()));
  for (std::size_t k = 0; k < g.joints.size(); ++k) {
    const ArmJoint& j = m.joint(g.joints[k]);
    const bool given = request.start.count(j.name) > 0 || scene.robot_state.count(j.name) > 0;
    if (!given) {
      throw FileError(files.request.string() + ": start_state: no value for joint '" + j.name + "' of group '" + g.name +
                      "' (nor in the scene's robot_state)");
    }
    s[static_cast<int>(k)] = request.start.count(j.name) > 0 ? request.start.at(j.name) : scene.robot_state.at(j.name);
    check_limits(j, s[static_cast<int>(k)], files.request.string() + ": start_state");
  }
  return s;
}

State goal_state(const ArmModel& m, const PlanningGroup& g, const MoveItRequest& request, const ArmFiles& files) {
  const std::string where = files.request.string() + ": goal_constraints[0]";
  State s(static_cast<int>(g.joints.size()));
  std::vector<bool> set(g.joints.size(), false);
  for (const auto& [name, value] : request.goal) {
    std::size_t k = 0;
    while (k < g.joints.size() && m.joint(g.joints[k]).name != name) ++k;
    if (k == g.joints.size()) throw FileError(where + ": joint '" + name + "' is not a movable joint of group '" + g.name + "'");
    check_limits(m.joint(g.joints[k]), value, where);
    s[static_cast<int>(k)] = value;
    set[k] = true;
  }
  for (std::size_t k = 0; k < g.joints.size(); ++k) {
    if (!set[k]) throw FileError(where + ": no goal for joint '" + m.joint(g.joints[k]).name + "' of group '" + g.name + "'");
  }
  return s;
}

// The link pairs never checked: the SRDF's disabled pairs and the scene's allowed pairs of links.
std::vector<std::pair<std::string, std::string>> disabled_pairs(const ArmModel& m, const Srdf& srdf, const MoveItScene& scene) {
  std::vector<std::pair<std::string, std::string>> out = srdf.disabled_collisions;
  for (std::size_t a = 0; a < m.links().size(); ++a) {
    for (std::size_t b = a + 1; b < m.links().size(); ++b) {
      if (scene.allowed.allowed(m.links()[a].name, m.links()[b].name)) out.emplace_back(m.links()[a].name, m.links()[b].name);
    }
  }
  return out;
}

// The scene's box, grown to the arm's reach around its root: what UAS's region features span.
Eigen::AlignedBox3d workspace(const MoveItScene& scene, double reach) {
  Eigen::AlignedBox3d box(Eigen::Vector3d::Constant(-reach), Eigen::Vector3d::Constant(reach));
  for (const Solid& s : scene.objects) box.extend(s.bounds());
  return box;
}

void check_seed(const ArmEnvironment& env, const State& s, const std::string& what, const ArmFiles& files) {
  const std::string contact = env.first_contact(s);
  if (!contact.empty()) {
    throw FileError(files.request.string() + ": " + what + ": the configuration is in collision: " + contact + " (scene " +
                    files.scene.filename().string() + ")");
  }
}

Problem finish_arm_problem(Problem p, const fs::path& scene_file, const fs::path& request_file, const MoveItRequest& request) {
  p.name = scene_file.parent_path().filename().string() + "-" + request_file.stem().string();
  p.file = request_file;
  p.defaults.planner = "rrt-connect";
  if (request.allowed_planning_time > 0.0) p.defaults.time_limit_s = request.allowed_planning_time;
  return p;
}

}  // namespace

ArmCollision parse_arm_collision(const std::string& text, const std::string& where) {
  if (text == "meshes") return ArmCollision::kMeshes;
  if (text == "spheres") return ArmCollision::kSpheres;
  throw ParameterError(where + ": '" + text + "' is not a collision model (meshes or spheres)");
}

ArmDescription load_arm_description(const fs::path& urdf, const fs::path& srdf, const std::vector<fs::path>& package_paths,
                                    const ArmCollisionOptions& collision) {
  ArmDescription d;
  d.urdf = urdf;
  d.srdf = srdf;
  d.model = std::make_shared<const ArmModel>(load_urdf(urdf, UrdfOptions{package_paths}));
  d.srdf_content = load_srdf(srdf);
  if (collision.model == ArmCollision::kSpheres) {
    d.exact_model = d.model;
    SphereCover cover;
    if (collision.spheres.empty()) {
      cover = cached_cover_with_spheres(*d.exact_model, collision.cache_dir);
    } else {
      try {
        cover = inflate_to_cover(*d.exact_model, load_sphere_urdf(collision.spheres, *d.exact_model), collision.spheres.string());
      } catch (const ParameterError& e) {
        throw FileError(collision.spheres.string() + ": " + e.what());
      }
    }
    d.exact_geometry = make_arm_geometry(*d.exact_model);
    d.model = std::make_shared<const ArmModel>(with_sphere_collision(*d.exact_model, cover.spheres));
    d.cover = std::move(cover.links);
  }
  d.geometry = make_arm_geometry(*d.model);
  return d;
}

Problem load_arm_problem(const ArmDescription& robot, const fs::path& scene_file, const fs::path& request_file) {
  const ArmFiles files{robot.urdf, robot.srdf, scene_file, request_file, {}, {}};
  const ArmModel& model = *robot.model;
  const MoveItScene scene = load_moveit_scene(scene_file);
  const MoveItRequest request = load_moveit_request(request_file);
  check_group_exists(robot.srdf_content, request.group, files);
  PlanningGroup group = resolve_group(model, robot.srdf_content, request.group, robot.srdf.string());

  Problem p;
  p.seeds.push_back(start_state(model, group, scene, request, files));
  p.seeds.push_back(goal_state(model, group, request, files));
  p.space = group_space(model, group, files);
  ArmKinematics kinematics(robot.model, std::move(group), start_values(model, scene, request));
  auto arm = std::make_shared<const ArmRobot>(std::move(kinematics), robot.geometry,
                                              disabled_pairs(model, robot.srdf_content, scene));
  auto world = std::make_shared<const SpatialWorld>(scene.objects, workspace(scene, arm->reach()));
  auto env = std::make_shared<const ArmEnvironment>(world, scene.object_ids, arm, scene.allowed);
  p.environment = env;
  if (robot.exact_model) {
    p.record_extra["spheres"] = static_cast<double>(arm->part_count());
    p.record_extra["sphere_kernels_avx2"] = std::string(ArmEnvironment::sphere_kernels_in_use()) == "avx2" ? 1.0 : 0.0;
    // The files' own geometry judges the request; a seed it accepts that the larger sphere model
    // does not makes the problem unsolvable in that model, which its runs report.
    const ArmKinematics exact_kinematics(robot.exact_model, arm->kinematics().group(), start_values(model, scene, request));
    auto exact_arm = std::make_shared<const ArmRobot>(exact_kinematics, robot.exact_geometry,
                                                      disabled_pairs(model, robot.srdf_content, scene));
    const ArmEnvironment exact(world, scene.object_ids, exact_arm, scene.allowed);
    check_seed(exact, p.seeds.front(), "start_state", files);
    check_seed(exact, p.seeds.back(), "goal_constraints[0]", files);
    for (const auto& [seed, what] : {std::pair{&p.seeds.front(), "start"}, std::pair{&p.seeds.back(), "goal"}}) {
      const std::string contact = env->first_contact(*seed);
      if (!contact.empty() && p.unsolvable_because.empty()) {
        p.unsolvable_because = std::string("the ") + what + " collides in the sphere model (" + contact +
                               ") though its meshes are free: plan with collision: meshes";
      }
    }
    return finish_arm_problem(std::move(p), scene_file, request_file, request);
  }
  check_seed(*env, p.seeds.front(), "start_state", files);
  check_seed(*env, p.seeds.back(), "goal_constraints[0]", files);
  return finish_arm_problem(std::move(p), scene_file, request_file, request);
}

Problem load_arm_problem(const ArmFiles& files) {
  return load_arm_problem(load_arm_description(files.urdf, files.srdf, files.package_paths, files.collision), files.scene,
                          files.request);
}

}  // namespace amp::world
