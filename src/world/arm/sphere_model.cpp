// The sphere model as an ArmModel: the links' collision solids replaced by their spheres, so that
// ArmRobot's motion coefficients, self pairs and FCL's reference checker all apply unchanged.
#include "amp/world/arm_spheres.hpp"

namespace amp::world {

ArmModel with_sphere_collision(const ArmModel& model, const std::vector<LinkSphere>& spheres) {
  std::vector<ArmLink> links = model.links();
  for (ArmLink& l : links) l.collision.clear();
  for (const LinkSphere& s : spheres) {
    links.at(static_cast<std::size_t>(s.link)).collision.push_back(Solid::sphere(s.radius, s.center));
  }
  return ArmModel(model.name(), std::move(links), model.joints());
}

}  // namespace amp::world
