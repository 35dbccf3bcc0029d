#pragma once
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "amp/core/state.hpp"
#include "amp/world/mesh_loader.hpp"

namespace amp::world {

// A world and its robot as triangle meshes in three dimensions, for the browser viewer
// (viz/viewer_page.hpp, `amp view`). Z is up. Every solid is already tessellated: boxes, spheres
// and cylinders as triangles, meshes as loaded. A 2-D world is raised into 3-D: its obstacles and
// its robot's links extruded upward from z = 0 (`flat`), so that the same viewer shows it.
struct SceneModel {
  // The obstacles, in the world frame (one mesh per obstacle, or per group of them).
  std::vector<TriangleMesh> obstacles;
  // Each robot link's mesh in its own frame, and its name (a URDF link's name; "body" for a rigid
  // body, "sphere" for a sphere robot; a SCARA's "column", "upper arm", "forearm", "wrist", "tool";
  // "link 0", "link 1", ... for a planar arm or linkage). Links without geometry have an empty mesh.
  std::vector<TriangleMesh> robot_links;
  std::vector<std::string> link_names;
  // The world's extent (the workspace bounds; for a 2-D world, z from 0 to the extrusion height).
  Eigen::AlignedBox3d bounds;
  // Whether the world is 2-D raised into 3-D (the viewer then looks from above first).
  bool flat = false;
};

// The role of a world that the 3-D viewer uses: its meshes once, and the robot's links posed at a
// state. Implemented by every Environment; its meshes are what the collision checker checks
// (collision geometry, not a visual stand-in), so what the page shows clearing an obstacle does.
class SceneModelSource {
 public:
  virtual ~SceneModelSource() = default;
  // Builds the meshes (allocates; called once per page).
  virtual SceneModel scene_model() const = 0;
  // The world pose of each of scene_model().robot_links at state s (`out` is resized to their
  // number). For a 2-D world, the planar pose lifted to z = 0, turned about z.
  virtual void robot_link_poses(const State& s, std::vector<Eigen::Isometry3d>& out) const = 0;
};

}  // namespace amp::world
