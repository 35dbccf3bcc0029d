#include "amp/world/outline_merge.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <unordered_set>
#include <utility>

#include "amp/world/planar_world.hpp"
#include "amp/world/polygon_geometry.hpp"

namespace amp::world {

namespace {

using Point = std::array<double, 2>;
using Edge = std::pair<Point, Point>;  // directed, from first to second

Point key(const Eigen::Vector2d& v) { return {v.x(), v.y()}; }
Eigen::Vector2d vec(const Point& p) { return {p[0], p[1]}; }

// The vertices of a counter-clockwise polygon read from its lexicographically smallest one: two
// copies of one polygon give the same list.
std::vector<Point> canonical(const Polygon& p) {
  std::vector<Point> v;
  v.reserve(p.vertices.size());
  for (const Eigen::Vector2d& q : p.vertices) v.push_back(key(q));
  std::rotate(v.begin(), std::min_element(v.begin(), v.end()), v.end());
  return v;
}

int find_root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// The outline of one group of counter-clockwise pieces: the directed edges that no piece of the
// group walks the other way, chained into one loop. Empty when they do not chain into exactly one
// simple loop covering the pieces' total area.
std::vector<Eigen::Vector2d> outline(const std::vector<const Polygon*>& group) {
  std::map<Edge, int> directed;
  double area = 0.0;
  for (const Polygon* p : group) {
    area += signed_area(p->vertices);
    const std::size_t n = p->vertices.size();
    for (std::size_t i = 0; i < n; ++i) {
      if (++directed[{key(p->vertices[i]), key(p->vertices[(i + 1) % n])}] > 1) return {};  // pieces overlap
    }
  }
  std::map<Point, Point> next;  // boundary edges by their start
  for (const auto& [e, count] : directed) {
    if (directed.count({e.second, e.first}) != 0) continue;  // shared by two pieces: inside
    if (!next.emplace(e.first, e.second).second) return {};  // two boundary edges leave one vertex
  }
  std::vector<Eigen::Vector2d> loop;
  Point at = next.begin()->first;
  do {
    loop.push_back(vec(at));
    at = next.at(at);
  } while (at != next.begin()->first && loop.size() <= next.size());
  if (loop.size() != next.size()) return {};  // a hole or a second loop
  // Drop vertices that lie exactly on the line of their neighbours (the diagonals' ends).
  for (bool changed = true; changed && loop.size() > 3;) {
    changed = false;
    for (std::size_t i = 0; i < loop.size() && loop.size() > 3; ++i) {
      const std::size_t h = (i + loop.size() - 1) % loop.size(), j = (i + 1) % loop.size();
      if (orient2d(loop[h], loop[i], loop[j]) == 0.0 && (loop[h] - loop[i]).dot(loop[j] - loop[i]) < 0.0) {
        loop.erase(loop.begin() + static_cast<std::ptrdiff_t>(i));
        changed = true;
      }
    }
  }
  const double loop_area = signed_area(loop);
  if (!is_simple(loop) || !(std::abs(loop_area - area) <= 1e-9 * area)) return {};
  return loop;
}

}  // namespace

std::vector<Polygon> merge_tiles(std::vector<Polygon> pieces) {
  std::vector<Polygon> out, unique;
  std::map<std::vector<Point>, int> seen;
  for (Polygon& p : pieces) {
    const double a = signed_area(p.vertices);
    if (p.vertices.size() < 3 || a == 0.0) {  // nothing to merge with
      out.push_back(std::move(p));
      continue;
    }
    if (a < 0.0) std::reverse(p.vertices.begin(), p.vertices.end());
    if (seen.emplace(canonical(p), static_cast<int>(unique.size())).second) unique.push_back(std::move(p));
  }
  // Groups: pieces joined by an edge that one walks forwards and the other backwards.
  std::vector<int> parent(unique.size());
  std::iota(parent.begin(), parent.end(), 0);
  std::map<Edge, int> owner;
  for (int k = 0; k < static_cast<int>(unique.size()); ++k) {
    const auto& v = unique[k].vertices;
    for (std::size_t i = 0; i < v.size(); ++i) owner.emplace(Edge{key(v[i]), key(v[(i + 1) % v.size()])}, k);
  }
  for (const auto& [e, k] : owner) {
    const auto twin = owner.find({e.second, e.first});
    if (twin != owner.end()) parent[find_root(parent, k)] = find_root(parent, twin->second);
  }
  std::map<int, std::vector<const Polygon*>> groups;  // ordered by root: the output is deterministic
  for (int k = 0; k < static_cast<int>(unique.size()); ++k) groups[find_root(parent, k)].push_back(&unique[k]);
  for (const auto& [root, group] : groups) {
    std::vector<Eigen::Vector2d> loop = group.size() > 1 ? outline(group) : std::vector<Eigen::Vector2d>{};
    if (loop.empty()) {
      for (const Polygon* p : group) out.push_back(*p);
    } else {
      out.push_back(Polygon{std::move(loop)});
    }
  }
  return out;
}

void drop_segments_on_polygon_edges(Shapes2d& shapes) {
  if (shapes.segments.empty() || shapes.polygons.empty()) return;
  Eigen::AlignedBox2d extent;
  for (const Polygon& p : shapes.polygons) extent.extend(bounding_box(p.vertices));
  // The polygons alone, for their edge grid.
  const PlanarWorld polygons(Shapes2d{shapes.polygons, {}}, extent);
  const PlanarGrid& grid = polygons.grid();
  std::vector<std::pair<double, double>> cover;
  std::unordered_set<int> visited;
  std::vector<Segment> kept;
  for (const Segment& s : shapes.segments) {
    const Eigen::Vector2d d = s.b - s.a;
    const Eigen::AlignedBox2d box(s.a.cwiseMin(s.b), s.a.cwiseMax(s.b));
    cover.clear();
    visited.clear();
    int x0, y0, x1, y1;
    if (grid.cell_range(box, x0, y0, x1, y1)) {
      for (int iy = y0; iy <= y1; ++iy) {
        for (int ix = x0; ix <= x1; ++ix) {
          for (int id : grid.edges_in(grid.cell_index(ix, iy))) {
            if (!visited.insert(id).second) continue;
            const PlanarEdge& e = polygons.edges()[id];
            if (orient2d(e.a, e.b, s.a) != 0.0 || orient2d(e.a, e.b, s.b) != 0.0) continue;
            const double ta = (e.a - s.a).dot(d) / d.squaredNorm(), tb = (e.b - s.a).dot(d) / d.squaredNorm();
            cover.emplace_back(std::min(ta, tb), std::max(ta, tb));
          }
        }
      }
    }
    std::sort(cover.begin(), cover.end());
    double reach = 0.0;  // [0, reach] of the segment is covered
    for (const auto& [lo, hi] : cover) {
      if (lo > reach) break;
      reach = std::max(reach, hi);
    }
    if (reach < 1.0) kept.push_back(s);
  }
  shapes.segments = std::move(kept);
}

}  // namespace amp::world
