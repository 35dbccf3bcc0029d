#include "amp/viz/mesh_decimation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

namespace amp::viz {

namespace {

using CellKey = std::tuple<long long, long long, long long>;

CellKey cell_of(const Eigen::Vector3d& v, double cell) {
  return {static_cast<long long>(std::floor(v.x() / cell)), static_cast<long long>(std::floor(v.y() / cell)),
          static_cast<long long>(std::floor(v.z() / cell))};
}

// The vertex index each original vertex merges into, and the merged vertices (cube means).
std::vector<int> merge_vertices(const world::TriangleMesh& mesh, double cell, std::vector<Eigen::Vector3d>& merged) {
  std::map<CellKey, int> index_of_cell;
  std::vector<int> count;
  std::vector<int> target(mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const auto [it, added] = index_of_cell.try_emplace(cell_of(mesh.vertices[i], cell), static_cast<int>(merged.size()));
    if (added) {
      merged.emplace_back(Eigen::Vector3d::Zero());
      count.push_back(0);
    }
    merged[static_cast<std::size_t>(it->second)] += mesh.vertices[i];
    ++count[static_cast<std::size_t>(it->second)];
    target[i] = it->second;
  }
  for (std::size_t k = 0; k < merged.size(); ++k) merged[k] /= count[k];
  return target;
}

std::size_t clustered_triangle_count(const world::TriangleMesh& mesh, double cell) {
  std::set<std::array<CellKey, 3>> kept;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    std::array<CellKey, 3> corners{cell_of(mesh.vertices[static_cast<std::size_t>(t[0])], cell),
                                   cell_of(mesh.vertices[static_cast<std::size_t>(t[1])], cell),
                                   cell_of(mesh.vertices[static_cast<std::size_t>(t[2])], cell)};
    if (corners[0] == corners[1] || corners[1] == corners[2] || corners[0] == corners[2]) continue;
    std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
    kept.insert(corners);
  }
  return kept.size();
}

}  // namespace

world::TriangleMesh cluster_vertices(const world::TriangleMesh& mesh, double cell) {
  world::TriangleMesh out;
  const std::vector<int> target = merge_vertices(mesh, cell, out.vertices);
  // A triangle is kept once per orientation: rotating its smallest index first keeps the winding.
  std::set<std::array<int, 3>> seen;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    std::array<int, 3> c{target[static_cast<std::size_t>(t[0])], target[static_cast<std::size_t>(t[1])],
                         target[static_cast<std::size_t>(t[2])]};
    if (c[0] == c[1] || c[1] == c[2] || c[0] == c[2]) continue;
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    if (seen.insert(c).second) out.triangles.emplace_back(c[0], c[1], c[2]);
  }
  return out;
}

double decimation_cell(const std::vector<const world::TriangleMesh*>& meshes, std::size_t max_triangles) {
  std::size_t total = 0;
  Eigen::AlignedBox3d box;
  for (const world::TriangleMesh* m : meshes) {
    total += m->triangles.size();
    box.extend(world::mesh_bounds(*m));
  }
  if (total <= max_triangles || box.isEmpty()) return 0.0;
  // From a cell as large as the whole scene (nearly nothing left) down, halving, while the
  // result still fits: the finest grid that fits. Twenty halvings reach a millionth of the scene.
  double cell = std::max(box.diagonal().maxCoeff(), 1e-12);
  for (int halving = 0; halving < 20; ++halving) {
    const double finer = cell / 2.0;
    std::size_t count = 0;
    for (const world::TriangleMesh* m : meshes) count += clustered_triangle_count(*m, finer);
    if (count > max_triangles) break;
    cell = finer;
  }
  return cell;
}

}  // namespace amp::viz
