#include "world/arm/sphere_scene.hpp"

#include <algorithm>
#include <cmath>

#include "amp/core/error.hpp"

namespace amp::world::detail {

namespace {

void push(SphereScene& out, const Solid& s, std::size_t object) {
  const Eigen::Matrix3d to_local = s.pose.linear().transpose();
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) out.r[row * 3 + col].push_back(to_local(row, col));
  }
  const Eigen::Vector3d c = s.pose.translation();
  out.cx.push_back(c.x());
  out.cy.push_back(c.y());
  out.cz.push_back(c.z());
  Eigen::Vector3d e = Eigen::Vector3d::Zero();
  if (s.kind == Solid::Kind::kBox) e = 0.5 * s.size;
  if (s.kind == Solid::Kind::kCylinder) e = Eigen::Vector3d(s.radius, 0.5 * s.length, 0.0);
  if (s.kind == Solid::Kind::kSphere) e = Eigen::Vector3d(s.radius, 0.0, 0.0);
  out.ex.push_back(e.x());
  out.ey.push_back(e.y());
  out.ez.push_back(e.z());
  out.bound.push_back(e.norm());
  out.object.push_back(object);
}

// The box's signed distance (Inigo Quilez's formulation): outside, the length of the positive
// excess; inside, the largest (least negative) excess.
double box_distance(const Eigen::Vector3d& q, const Eigen::Vector3d& half) {
  const Eigen::Vector3d d = q.cwiseAbs() - half;
  return d.cwiseMax(0.0).norm() + std::min(d.maxCoeff(), 0.0);
}

// A capped cylinder about z: the same in the (radial, axial) plane.
double cylinder_distance(const Eigen::Vector3d& q, double radius, double half_length) {
  // sqrt, not hypot: no overflow is possible at these scales, and hypot costs ten times as much.
  const double dr = std::sqrt(q.x() * q.x() + q.y() * q.y()) - radius;
  const double dz = std::abs(q.z()) - half_length;
  const double orad = std::max(dr, 0.0), oz = std::max(dz, 0.0);
  return std::sqrt(orad * orad + oz * oz) + std::min(std::max(dr, dz), 0.0);
}

}  // namespace

bool sphere_scene_supported(const std::vector<Solid>& solids) {
  return std::none_of(solids.begin(), solids.end(), [](const Solid& s) { return s.kind == Solid::Kind::kMesh; });
}

SphereScene make_sphere_scene(const std::vector<Solid>& solids) {
  SphereScene out;
  for (const Solid::Kind kind : {Solid::Kind::kBox, Solid::Kind::kCylinder, Solid::Kind::kSphere}) {
    for (std::size_t i = 0; i < solids.size(); ++i) {
      if (solids[i].kind == kind) push(out, solids[i], i);
    }
  }
  for (const Solid& s : solids) {
    if (s.kind == Solid::Kind::kBox) ++out.boxes;
    if (s.kind == Solid::Kind::kCylinder) ++out.cylinders;
    if (s.kind == Solid::Kind::kSphere) ++out.spheres;
    if (s.kind == Solid::Kind::kMesh) throw ParameterError("sphere model: scene meshes are checked by FCL, not here");
  }
  return out;
}

double obstacle_distance(const SphereScene& scene, std::size_t i, const Eigen::Vector3d& p) {
  const Eigen::Vector3d d(p.x() - scene.cx[i], p.y() - scene.cy[i], p.z() - scene.cz[i]);
  if (i >= scene.boxes + scene.cylinders) return d.norm() - scene.ex[i];
  Eigen::Vector3d q;
  for (int row = 0; row < 3; ++row) {
    q[row] = scene.r[row * 3][i] * d.x() + scene.r[row * 3 + 1][i] * d.y() + scene.r[row * 3 + 2][i] * d.z();
  }
  if (i < scene.boxes) return box_distance(q, Eigen::Vector3d(scene.ex[i], scene.ey[i], scene.ez[i]));
  return cylinder_distance(q, scene.ex[i], scene.ey[i]);
}

}  // namespace amp::world::detail
