#include "amp/world/arm_environment.hpp"

#include "amp/core/error.hpp"
#include "amp/world/solid_mesh.hpp"
#include "world/arm/arm_checker.hpp"
#include "world/arm/sphere_checker.hpp"
#include "world/arm/sphere_kernels.hpp"
#include "world/spatial/projection.hpp"

namespace amp::world {

ArmEnvironment::ArmEnvironment(std::shared_ptr<const SpatialWorld> scene, std::vector<std::string> object_ids,
                               std::shared_ptr<const ArmRobot> robot, const AllowedCollisions& allowed)
    : scene_(std::move(scene)), object_ids_(std::move(object_ids)), robot_(std::move(robot)) {
  const auto& links = robot_->model().links();
  allowed_.assign(object_ids_.size(), std::vector<bool>(links.size(), false));
  for (std::size_t i = 0; i < object_ids_.size(); ++i) {
    for (std::size_t l = 0; l < links.size(); ++l) {
      allowed_[i][l] = !allowed.empty() && allowed.allowed(object_ids_[i], links[l].name);
    }
  }
  sphere_checked_ = detail::sphere_checker_applies(*this);
}

bool ArmEnvironment::allowed(std::size_t object, int link) const {
  return object < allowed_.size() && allowed_[object][static_cast<std::size_t>(link)];
}

std::unique_ptr<ValidityChecker> ArmEnvironment::make_checker(core::Counters& counters) const {
  if (sphere_checked_) return std::make_unique<detail::SphereChecker>(*this, counters, detail::sphere_kernels());
  return make_fcl_checker(counters);
}

std::unique_ptr<ValidityChecker> ArmEnvironment::make_sphere_checker(core::Counters& counters, SphereIsa isa) const {
  if (!sphere_checked_) throw ParameterError("arm: the sphere checker needs a robot of spheres in a scene of primitives");
  const detail::SphereKernels& kernels = isa == SphereIsa::kBaseline ? detail::sphere_kernels_baseline()
                                         : isa == SphereIsa::kAvx2   ? detail::sphere_kernels_avx2()
                                                                     : detail::sphere_kernels();
  return std::make_unique<detail::SphereChecker>(*this, counters, kernels);
}

const char* ArmEnvironment::sphere_kernels_in_use() { return detail::sphere_kernels().name; }

std::unique_ptr<ValidityChecker> ArmEnvironment::make_fcl_checker(core::Counters& counters) const {
  const std::lock_guard<std::mutex> lock(make_mutex_);
  return std::make_unique<detail::ArmChecker>(*this, counters);
}

std::string ArmEnvironment::first_contact(const State& s) const {
  core::Counters scratch;
  std::unique_ptr<detail::ArmChecker> checker;
  {
    const std::lock_guard<std::mutex> lock(make_mutex_);
    checker = std::make_unique<detail::ArmChecker>(*this, scratch);
  }
  return checker->first_contact(s);
}

Outline ArmEnvironment::obstacles_seen_from(const Eigen::Isometry3d& view) const {
  Outline outline;
  for (const Solid& s : scene_->obstacles()) detail::project_solid(s, view, true, outline.shapes);
  return outline;
}

Shapes2d ArmEnvironment::robot_seen_from(const Eigen::Isometry3d& view, const State& s) const {
  std::vector<Eigen::Isometry3d> poses(robot_->kinematics().link_count());
  robot_->kinematics().link_poses(s, poses.data());
  Shapes2d out;
  for (std::size_t l = 0; l < poses.size(); ++l) {
    for (const Solid& solid : robot_->model().links()[l].collision) detail::project_solid(solid, view * poses[l], false, out);
  }
  return out;
}

SceneModel ArmEnvironment::scene_model() const {
  SceneModel model;
  for (const Solid& s : scene_->obstacles()) model.obstacles.push_back(solid_mesh(s));
  for (const ArmLink& link : robot_->model().links()) {
    TriangleMesh mesh;
    for (const Solid& s : link.collision) append_mesh(mesh, solid_mesh(s));
    model.robot_links.push_back(std::move(mesh));
    model.link_names.push_back(link.name);
  }
  model.bounds = scene_->bounds();
  return model;
}

void ArmEnvironment::robot_link_poses(const State& s, std::vector<Eigen::Isometry3d>& out) const {
  out.resize(robot_->kinematics().link_count());
  robot_->kinematics().link_poses(s, out.data());
}

Outline ArmEnvironment::obstacle_outline() const { return obstacles_seen_from(Eigen::Isometry3d::Identity()); }
Shapes2d ArmEnvironment::robot_outline(const State& s) const { return robot_seen_from(Eigen::Isometry3d::Identity(), s); }
Outline ArmEnvironment::obstacle_front_outline() const { return obstacles_seen_from(detail::front_view_frame()); }
Shapes2d ArmEnvironment::robot_front_outline(const State& s) const { return robot_seen_from(detail::front_view_frame(), s); }

}  // namespace amp::world
