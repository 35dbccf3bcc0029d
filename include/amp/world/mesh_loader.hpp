#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Geometry>

namespace amp::world {

// A triangle soup in Z-up coordinates: vertices and index triples into them.
struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> triangles;
};

// Which axis of the file points up. kAuto: Y for COLLADA files declaring <up_axis>Y_UP</up_axis>
// (or without <up_axis>: the COLLADA default) and for scenes whose "UpAxis" metadata says 1 (FBX);
// Z for everything else (STL, PLY and OBJ carry no convention; robotics files are Z-up).
// kZ also means "as assimp reads it": OMPL.app applies no conversion of its own, so its .cfg
// problems are loaded with kZ (a Z_UP COLLADA file then stays in its own frame, a Y_UP one is not
// turned).
enum class UpAxis { kAuto, kY, kZ };

// Loads every mesh of the scene with assimp (OBJ, STL, PLY, DAE, ...) as OMPL.app does: importer
// defaults, triangulating polygons, joining identical vertices, applying the node transforms
// recursively. Every instanced vertex is kept (those of points and lines too, so that
// vertex_mean() is OMPL.app's robot centre); only triangles become faces. Y-up content is rotated
// to Z-up ((x, y, z) -> (x, -z, y)).
// Throws FileError naming the file when assimp cannot read it or it holds no triangle.
TriangleMesh load_mesh(const std::filesystem::path& file, UpAxis up = UpAxis::kAuto);

// Parses "y" / "z" (the `up:` field of problem files); throws ParameterError otherwise.
UpAxis parse_up_axis(const std::string& text);

// Axis-aligned bounds of the vertices (empty box for an empty mesh).
Eigen::AlignedBox3d mesh_bounds(const TriangleMesh& mesh);
// Mean of the vertices: OMPL.app re-centres robot meshes on it (scene::sceneCenter: every vertex
// of every instanced mesh, after the node transforms).
Eigen::Vector3d vertex_mean(const TriangleMesh& mesh);

}  // namespace amp::world
