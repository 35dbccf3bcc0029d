#include "amp/world/solid_mesh.hpp"

#include <cmath>
#include <numbers>

namespace amp::world {

namespace {

int add_vertex(TriangleMesh& m, const Eigen::Vector3d& v) {
  m.vertices.push_back(v);
  return static_cast<int>(m.vertices.size()) - 1;
}

// Corners indexed by bits (x, y, z) as Solid::hull_points has them; faces counter-clockwise seen
// from outside.
TriangleMesh unit_box(const Eigen::Vector3d& size) {
  TriangleMesh m;
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d corner(i & 1 ? 0.5 : -0.5, i & 2 ? 0.5 : -0.5, i & 4 ? 0.5 : -0.5);
    m.vertices.push_back(corner.cwiseProduct(size));
  }
  m.triangles = {{0, 2, 3}, {0, 3, 1},   // -z
                 {4, 5, 7}, {4, 7, 6},   // +z
                 {0, 1, 5}, {0, 5, 4},   // -y
                 {2, 6, 7}, {2, 7, 3},   // +y
                 {0, 4, 6}, {0, 6, 2},   // -x
                 {1, 3, 7}, {1, 7, 5}};  // +x
  return m;
}

// A kRoundSides-gon prism around the local z axis, centred on the origin.
TriangleMesh unit_cylinder(double radius, double length) {
  TriangleMesh m;
  const int n = kRoundSides;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * i / n;
    const Eigen::Vector2d p(radius * std::cos(a), radius * std::sin(a));
    add_vertex(m, {p.x(), p.y(), -0.5 * length});  // 2 i
    add_vertex(m, {p.x(), p.y(), 0.5 * length});   // 2 i + 1
  }
  const int bottom = add_vertex(m, {0.0, 0.0, -0.5 * length});
  const int top = add_vertex(m, {0.0, 0.0, 0.5 * length});
  for (int i = 0; i < n; ++i) {
    const int a0 = 2 * i, a1 = 2 * i + 1, b0 = 2 * ((i + 1) % n), b1 = b0 + 1;
    m.triangles.emplace_back(a0, b0, b1);
    m.triangles.emplace_back(a0, b1, a1);
    m.triangles.emplace_back(top, a1, b1);
    m.triangles.emplace_back(bottom, b0, a0);
  }
  return m;
}

// Latitude-longitude sphere: two poles and kSphereStacks - 1 rings of kSphereSlices vertices.
TriangleMesh unit_sphere(double radius) {
  TriangleMesh m;
  constexpr int slices = kSphereSlices, rings = kSphereStacks - 1;
  const int south = add_vertex(m, {0.0, 0.0, -radius});
  for (int r = 0; r < rings; ++r) {
    const double polar = std::numbers::pi * (r + 1) / kSphereStacks;  // from the south pole
    const double z = -radius * std::cos(polar), rho = radius * std::sin(polar);
    for (int i = 0; i < slices; ++i) {
      const double a = 2.0 * std::numbers::pi * i / slices;
      add_vertex(m, {rho * std::cos(a), rho * std::sin(a), z});
    }
  }
  const int north = add_vertex(m, {0.0, 0.0, radius});
  auto at = [](int ring, int i) { return 1 + ring * slices + (i % slices); };  // a constant: no capture
  for (int i = 0; i < slices; ++i) {
    m.triangles.emplace_back(south, at(0, i + 1), at(0, i));
    m.triangles.emplace_back(north, at(rings - 1, i), at(rings - 1, i + 1));
    for (int r = 0; r + 1 < rings; ++r) {
      m.triangles.emplace_back(at(r, i), at(r, i + 1), at(r + 1, i + 1));
      m.triangles.emplace_back(at(r, i), at(r + 1, i + 1), at(r + 1, i));
    }
  }
  return m;
}

TriangleMesh local_mesh(const Solid& solid) {
  switch (solid.kind) {
    case Solid::Kind::kBox:
      return unit_box(solid.size);
    case Solid::Kind::kSphere:
      return unit_sphere(solid.radius);
    case Solid::Kind::kCylinder:
      return unit_cylinder(solid.radius, solid.length);
    case Solid::Kind::kMesh:
      break;
  }
  return solid.mesh ? *solid.mesh : TriangleMesh{};
}

}  // namespace

TriangleMesh transformed_mesh(const TriangleMesh& mesh, const Eigen::Isometry3d& pose) {
  TriangleMesh out;
  out.triangles = mesh.triangles;
  out.vertices.reserve(mesh.vertices.size());
  for (const Eigen::Vector3d& v : mesh.vertices) out.vertices.push_back(pose * v);
  return out;
}

TriangleMesh solid_mesh(const Solid& solid) { return transformed_mesh(local_mesh(solid), solid.pose); }

void append_mesh(TriangleMesh& into, const TriangleMesh& part) {
  const int offset = static_cast<int>(into.vertices.size());
  into.vertices.insert(into.vertices.end(), part.vertices.begin(), part.vertices.end());
  into.triangles.reserve(into.triangles.size() + part.triangles.size());
  for (const Eigen::Vector3i& t : part.triangles) into.triangles.push_back(t.array() + offset);
}

}  // namespace amp::world
