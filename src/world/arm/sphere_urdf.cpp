// A spherized URDF (VAMP's panda_spherized.urdf and the like): the same links as the robot's URDF,
// each link's <collision> elements spheres. Read with the ordinary URDF loader, then matched by name.
#include <algorithm>
#include <string>
#include <vector>

#include "amp/core/error.hpp"
#include "amp/world/arm_spheres.hpp"

namespace amp::world {

namespace {

const char* kind_name(Solid::Kind kind) {
  switch (kind) {
    case Solid::Kind::kBox:
      return "a box";
    case Solid::Kind::kCylinder:
      return "a cylinder";
    case Solid::Kind::kMesh:
      return "a mesh";
    case Solid::Kind::kSphere:
      break;
  }
  return "a sphere";
}

}  // namespace

std::vector<LinkSphere> load_sphere_urdf(const std::filesystem::path& file, const ArmModel& model) {
  const ArmModel spherized = load_urdf(file);
  std::vector<LinkSphere> out;
  for (const ArmLink& link : spherized.links()) {
    const int index = model.link_index(link.name);
    if (index < 0) {
      throw FileError(file.string() + ": link '" + link.name + "' is not a link of robot '" + model.name() + "'");
    }
    for (std::size_t i = 0; i < link.collision.size(); ++i) {
      const Solid& solid = link.collision[i];
      if (solid.kind != Solid::Kind::kSphere) {
        throw FileError(file.string() + ": link '" + link.name + "': <collision> " + std::to_string(i + 1) + " is " +
                        kind_name(solid.kind) + ", not a sphere");
      }
      out.push_back({index, solid.pose.translation(), solid.radius});
    }
  }
  // The file's links come in its own tree order; a SphereCover lists them in the model's.
  std::stable_sort(out.begin(), out.end(), [](const LinkSphere& a, const LinkSphere& b) { return a.link < b.link; });
  return out;
}

}  // namespace amp::world
