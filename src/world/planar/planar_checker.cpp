#include "amp/world/planar_checker.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "amp/core/error.hpp"
#include "amp/world/polygon_geometry.hpp"

namespace amp::world {

PlanarChecker::PlanarChecker(std::shared_ptr<const PlanarWorld> world, PlanarRobot robot, core::Counters& counters,
                             PlanarBoundsCheck bounds_check)
    : ValidityChecker(counters), world_(std::move(world)), robot_(std::move(robot)), bounds_check_(bounds_check) {
  if (!world_) throw ParameterError("PlanarChecker: no world");
  // Flatten the robot's shapes, link by link, so that a check walks contiguous arrays.
  for (int l = 0; l < robot_.link_count(); ++l) {
    const Shapes2d& link = robot_.links()[l];
    LinkRange range;
    range.polygon_begin = static_cast<int>(polygons_.size());
    range.circle_begin = static_cast<int>(circles_.size());
    for (const Polygon& p : link.polygons) {
      polygons_.push_back({l, static_cast<int>(local_.size()), static_cast<int>(p.vertices.size())});
      local_.insert(local_.end(), p.vertices.begin(), p.vertices.end());
    }
    for (const Circle& c : link.circles) circles_.push_back({l, c.center, c.radius});
    range.polygon_end = static_cast<int>(polygons_.size());
    range.circle_end = static_cast<int>(circles_.size());
    link_ranges_.push_back(range);
  }
  int first = 0;
  for (const Polygon& p : world_->obstacles().polygons) {
    polygon_first_edge_.push_back(first);
    first += static_cast<int>(p.vertices.size());
  }
  poses_.resize(robot_.link_count());
  placed_.resize(local_.size());
  polygon_boxes_.resize(polygons_.size());
  circle_centers_.resize(circles_.size());
  link_boxes_.resize(robot_.link_count());
  edge_stamp_.assign(world_->edges().size(), 0);
  polygon_stamp_.assign(world_->obstacles().polygons.size(), 0);
  circle_stamp_.assign(world_->obstacles().circles.size(), 0);
  parity_scratch_.reserve(world_->grid().max_parity_items());
  // Reach of each link's shapes from its own origin, then accumulated from the tip inwards.
  const int n = robot_.link_count();
  std::vector<double> own(n, 0.0);
  for (int l = 0; l < n; ++l) {
    for (const Polygon& p : robot_.links()[l].polygons) {
      for (const Eigen::Vector2d& v : p.vertices) own[l] = std::max(own[l], v.norm());
    }
    for (const Circle& c : robot_.links()[l].circles) own[l] = std::max(own[l], c.center.norm() + c.radius);
  }
  joint_reach_.assign(n, 0.0);
  const auto& specs = robot_.link_specs();
  for (int j = n - 1; j >= 0; --j) {
    const double length = j < static_cast<int>(specs.size()) ? specs[j].length : 0.0;
    joint_reach_[j] = std::max(own[j], j + 1 < n ? length + joint_reach_[j + 1] : 0.0);
  }
}

std::uint32_t PlanarChecker::next_stamp() const {
  if (++stamp_ == 0) {  // wrapped after 2^32 queries: forget every old mark
    std::fill(edge_stamp_.begin(), edge_stamp_.end(), 0);
    std::fill(polygon_stamp_.begin(), polygon_stamp_.end(), 0);
    std::fill(circle_stamp_.begin(), circle_stamp_.end(), 0);
    stamp_ = 1;
  }
  return stamp_;
}

bool PlanarChecker::place(const State& s) const {
  if (s.size() != robot_.state_dimension()) {
    throw ParameterError("planar checker: state has " + std::to_string(s.size()) + " coordinates, the robot needs " +
                         std::to_string(robot_.state_dimension()));
  }
  if (!s.allFinite()) return false;
  robot_.link_poses(s, poses_.data());
  for (auto& b : link_boxes_) b.setEmpty();
  for (int l = 0; l < robot_.link_count(); ++l) {
    const Pose2& pose = poses_[l];
    const double c = std::cos(pose.theta);
    const double sn = std::sin(pose.theta);
    const LinkRange& range = link_ranges_[l];
    for (int k = range.polygon_begin; k < range.polygon_end; ++k) {
      const BodyPolygon& p = polygons_[k];
      Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
      Eigen::Vector2d hi = -lo;
      for (int i = p.first; i < p.first + p.count; ++i) {
        const Eigen::Vector2d w = transform_point(pose, c, sn, local_[i]);
        placed_[i] = w;
        lo = lo.cwiseMin(w);
        hi = hi.cwiseMax(w);
      }
      polygon_boxes_[k] = Eigen::AlignedBox2d(lo, hi);
      link_boxes_[l].extend(polygon_boxes_[k]);
    }
    for (int k = range.circle_begin; k < range.circle_end; ++k) {
      circle_centers_[k] = transform_point(pose, c, sn, circles_[k].center);
      const Eigen::Vector2d r = Eigen::Vector2d::Constant(circles_[k].radius);
      link_boxes_[l].extend(Eigen::AlignedBox2d(circle_centers_[k] - r, circle_centers_[k] + r));
    }
  }
  return true;
}

bool PlanarChecker::inside_bounds() const {
  const Eigen::AlignedBox2d& bounds = world_->bounds();
  if (bounds_check_ == PlanarBoundsCheck::kReferencePoint) {
    return bounds.contains(reference_point_placed());
  }
  for (const auto& b : link_boxes_) {
    if (!bounds.contains(b)) return false;
  }
  return true;
}

bool PlanarChecker::check(const State& s) const {
  if (!place(s) || !inside_bounds()) return false;
  for (int k = 0; k < static_cast<int>(polygons_.size()); ++k) {
    if (polygon_hits_obstacles(k)) return false;
  }
  for (int k = 0; k < static_cast<int>(circles_.size()); ++k) {
    if (circle_hits_obstacles(k)) return false;
  }
  return !(robot_.has_self_collision() && self_collides());
}

template <class OnEdge, class OnCircle>
bool PlanarChecker::any_near(const Eigen::AlignedBox2d& box, OnEdge&& on_edge, OnCircle&& on_circle) const {
  // Visits each obstacle edge and circle whose cell and box meet `box` once (stamps), until a
  // callback reports a hit.
  const PlanarGrid& grid = world_->grid();
  const auto& edges = world_->edges();
  int x0, y0, x1, y1;
  if (!grid.cell_range(box, x0, y0, x1, y1)) return false;  // off the grid: clear of every obstacle
  const std::uint32_t st = next_stamp();
  for (int iy = y0; iy <= y1; ++iy) {
    for (int ix = x0; ix <= x1; ++ix) {
      const int cell = grid.cell_index(ix, iy);
      for (int id : grid.edges_in(cell)) {
        if (edge_stamp_[id] == st) continue;
        edge_stamp_[id] = st;
        const PlanarEdge& e = edges[id];
        if (e.box.intersects(box) && on_edge(e, st)) return true;
      }
      for (int id : grid.circles_in(cell)) {
        if (circle_stamp_[id] == st) continue;
        circle_stamp_[id] = st;
        if (world_->circle_boxes()[id].intersects(box) && on_circle(world_->obstacles().circles[id])) return true;
      }
    }
  }
  return false;
}

bool PlanarChecker::polygon_hits_obstacles(int k) const {
  const std::span<const Eigen::Vector2d> v = placed(k);
  const Eigen::AlignedBox2d& box = polygon_boxes_[k];
  const std::size_t n = v.size();
  const bool hit = any_near(
      box,
      [&](const PlanarEdge& e, std::uint32_t st) {
        // Early exit: the edge's line leaves every robot vertex strictly on one side.
        bool pos = false, neg = false;
        for (std::size_t i = 0; i < n; ++i) {
          const double o = orient2d(e.a, e.b, v[i]);
          pos = pos || o >= 0.0;
          neg = neg || o <= 0.0;
        }
        if (pos && neg) {
          for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
            if (segments_intersect(v[j], v[i], e.a, e.b)) return true;
          }
        }
        // An obstacle wholly inside the robot has no edge crossing: test one of its vertices.
        const int p = e.polygon;
        if (p < 0) return box.contains(e.a) && point_in_polygon(e.a, v);  // a segment wall
        if (polygon_stamp_[p] != st) {
          polygon_stamp_[p] = st;
          if (box.contains(world_->polygon_boxes()[p]) && point_in_polygon(e.a, v)) return true;
        }
        return false;
      },
      [&](const Circle& c) { return polygon_circle_overlap(v, c.center, c.radius); });
  if (hit) return true;
  // No boundary contact: the robot polygon may still lie wholly inside an obstacle polygon.
  return world_->point_in_obstacle_polygon(v[0], parity_scratch_);
}

bool PlanarChecker::circle_hits_obstacles(int k) const {
  const Eigen::Vector2d& c = circle_centers_[k];
  const double r = circles_[k].radius;
  const Eigen::AlignedBox2d box(c - Eigen::Vector2d::Constant(r), c + Eigen::Vector2d::Constant(r));
  const bool hit = any_near(
      box, [&](const PlanarEdge& e, std::uint32_t) { return point_segment_distance_sq(c, e.a, e.b) <= r * r; },
      [&](const Circle& o) {
        const double reach = r + o.radius;
        return (c - o.center).squaredNorm() <= reach * reach;
      });
  if (hit) return true;
  // An obstacle polygon inside the disc would have an edge within r: only the centre is left.
  return world_->point_in_obstacle_polygon(c, parity_scratch_);
}

bool PlanarChecker::self_collides() const {
  const int n = robot_.link_count();
  for (int i = 0; i < n; ++i) {
    for (int j = i + 2; j < n; ++j) {  // adjacent links share a joint and may overlap there
      if (!link_boxes_[i].intersects(link_boxes_[j])) continue;
      const LinkRange& a = link_ranges_[i];
      const LinkRange& b = link_ranges_[j];
      for (int p = a.polygon_begin; p < a.polygon_end; ++p) {
        for (int q = b.polygon_begin; q < b.polygon_end; ++q) {
          if (polygon_boxes_[p].intersects(polygon_boxes_[q]) && polygons_overlap(placed(p), placed(q))) return true;
        }
        for (int q = b.circle_begin; q < b.circle_end; ++q) {
          if (polygon_circle_overlap(placed(p), circle_centers_[q], circles_[q].radius)) return true;
        }
      }
      for (int p = a.circle_begin; p < a.circle_end; ++p) {
        for (int q = b.polygon_begin; q < b.polygon_end; ++q) {
          if (polygon_circle_overlap(placed(q), circle_centers_[p], circles_[p].radius)) return true;
        }
        for (int q = b.circle_begin; q < b.circle_end; ++q) {
          const double reach = circles_[p].radius + circles_[q].radius;
          if ((circle_centers_[p] - circle_centers_[q]).squaredNorm() <= reach * reach) return true;
        }
      }
    }
  }
  return false;
}

}  // namespace amp::world
