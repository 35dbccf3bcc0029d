// GridEnvironment's SceneModelSource role: a map raised into 3-D for the viewer.
#include <map>
#include <utility>
#include <vector>

#include "amp/world/grid_environment.hpp"
#include "amp/world/solid_mesh.hpp"

namespace amp::world {

namespace {

// A block of blocked cells: columns [x0, x1), rows [y0, y1).
struct CellRect {
  int x0, x1, y0, y1;
};

// Blocked cells merged greedily: runs along each row, a run stacked onto the identical run of the
// row below. A map's walls are mostly long straight runs, so a large map becomes a few thousand
// boxes rather than a box per cell.
std::vector<CellRect> blocked_rects(const OccupancyGrid& grid) {
  std::vector<CellRect> out;
  std::map<std::pair<int, int>, int> open, still_open;  // run (x0, x1) -> first row
  for (int y = 0; y <= grid.height(); ++y) {
    still_open.clear();
    for (int x = 0; y < grid.height() && x < grid.width();) {
      if (!grid.blocked(x, y)) {
        ++x;
        continue;
      }
      const int x0 = x;
      while (x < grid.width() && grid.blocked(x, y)) ++x;
      const auto it = open.find({x0, x});
      still_open[{x0, x}] = it == open.end() ? y : it->second;
    }
    for (const auto& [run, y0] : open) {
      if (still_open.count(run) == 0) out.push_back({run.first, run.second, y0, y});
    }
    open.swap(still_open);
  }
  return out;
}

}  // namespace

SceneModel GridEnvironment::scene_model() const {
  const OccupancyGrid& g = grid();
  const FlatHeights h = flat_heights(g.extent());
  SceneModel model;
  model.flat = true;
  model.bounds = flat_bounds(g.extent(), h);
  TriangleMesh walls;
  for (const CellRect& r : blocked_rects(g)) {
    Eigen::AlignedBox2d box = g.cell_box(r.x0, r.y0);
    box.extend(g.cell_box(r.x1 - 1, r.y1 - 1));
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() << box.center(), 0.5 * h.obstacles;
    append_mesh(walls, solid_mesh(Solid::box({box.sizes().x(), box.sizes().y(), h.obstacles}, pose)));
  }
  if (!walls.triangles.empty()) model.obstacles.push_back(std::move(walls));
  Shapes2d body = robot_.body;
  if (robot_.kind != GridRobot::Kind::kRigid) {
    // A point robot occupies the cell it is in: drawn as a disc across that cell.
    const double r = robot_.kind == GridRobot::Kind::kDisc ? robot_.radius : 0.5 * g.resolution();
    body = Shapes2d{{}, {Circle{Eigen::Vector2d::Zero(), r}}};
  }
  model.robot_links.push_back(extrude_shapes(body, 0.0, h.robot, h.wall_thickness));
  model.link_names.emplace_back("body");
  return model;
}

void GridEnvironment::robot_link_poses(const State& s, std::vector<Eigen::Isometry3d>& out) const {
  out.resize(1);
  out[0] = lift_pose({s[0], s[1], state_dimension() == 3 ? s[2] : 0.0});
}

}  // namespace amp::world
