#pragma once
// Private to sphere_cover.cpp: a link's collision solids cut into small convex pieces, each given by
// its corners in the link frame. A convex set lies in a ball iff all its corners do, so spheres that
// hold every piece's corners cover the solids: that is the whole proof of the sphere model.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include <Eigen/Geometry>

#include "amp/core/error.hpp"
#include "amp/world/spatial_world.hpp"

namespace amp::world::detail {

// Caps on the cutting, so that a large solid with a small piece size costs bounded memory: past them
// the pieces of that solid are larger than asked, which keeps the cover and only loosens it.
constexpr int kMaxSplitDepth = 8;                    // a triangle becomes at most 4^8 pieces
constexpr std::size_t kMaxCellsPerSolid = 1u << 15;  // box and cylinder grid cells
// Pieces per link at most: a link of many large triangles is cut coarser (larger pieces still make
// a cover, a looser one) rather than into tens of millions of pieces. The Panda's largest link
// makes about 60,000.
constexpr double kMaxPiecesPerLink = 1 << 20;
constexpr double kCoarser = 1.25;

// A sphere solid: kept whole, it needs no pieces.
struct Ball {
  Eigen::Vector3d center;
  double radius;
};

struct LinkPieces {
  std::vector<Eigen::Vector3d> corners;  // every piece's corners, piece after piece
  std::vector<int> first{0};             // piece i owns corners [first[i], first[i + 1])
  std::vector<Ball> balls;
  Eigen::AlignedBox3d box;  // the solids' bounds in the link frame (empty without solids)

  int count() const { return static_cast<int>(first.size()) - 1; }
  std::span<const Eigen::Vector3d> piece(int i) const {
    const auto b = static_cast<std::size_t>(first[static_cast<std::size_t>(i)]);
    const auto e = static_cast<std::size_t>(first[static_cast<std::size_t>(i) + 1]);
    return {corners.data() + b, e - b};
  }
  bool empty() const { return count() == 0 && balls.empty(); }
  void close_piece() { first.push_back(static_cast<int>(corners.size())); }
};

// Midpoint 4-split until the longest edge is at most `size` (FCL tests a mesh as its triangles, so
// their surface is what must be covered).
inline void add_triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, double size,
                         int depth_left, LinkPieces& out) {
  const double longest = std::max({(a - b).squaredNorm(), (b - c).squaredNorm(), (c - a).squaredNorm()});
  if (depth_left == 0 || longest <= size * size) {
    out.corners.insert(out.corners.end(), {a, b, c});
    out.close_piece();
    return;
  }
  const Eigen::Vector3d ab = 0.5 * (a + b), bc = 0.5 * (b + c), ca = 0.5 * (c + a);
  add_triangle(a, ab, ca, size, depth_left - 1, out);
  add_triangle(ab, b, bc, size, depth_left - 1, out);
  add_triangle(ca, bc, c, size, depth_left - 1, out);
  add_triangle(ab, bc, ca, size, depth_left - 1, out);
}

inline void add_mesh(const Solid& solid, double size, LinkPieces& out) {
  std::vector<Eigen::Vector3d> v;
  v.reserve(solid.mesh->vertices.size());
  for (const Eigen::Vector3d& p : solid.mesh->vertices) v.push_back(solid.pose * p);
  for (const Eigen::Vector3i& t : solid.mesh->triangles) {
    add_triangle(v[static_cast<std::size_t>(t[0])], v[static_cast<std::size_t>(t[1])], v[static_cast<std::size_t>(t[2])], size,
                 kMaxSplitDepth, out);
  }
}

// Cells per axis for a grid over `extent` with sides at most `size`, widened past the cell cap
// (counted in doubles, which do not overflow).
inline Eigen::Vector3i grid_cells(const Eigen::Vector3d& extent, double size) {
  constexpr double kWiden = 1.25;
  for (;; size *= kWiden) {
    const Eigen::Vector3d n = (extent / size).array().ceil().max(1.0);
    if (n.prod() <= static_cast<double>(kMaxCellsPerSolid)) return n.cast<int>();
  }
}

// The cells of a grid over the centred box `extent` (solid-local), posed into the link frame; a cell
// is kept when `keep(lo, hi)` says it meets the solid.
template <class Keep>
void add_cells(const Solid& solid, const Eigen::Vector3d& extent, double size, Keep keep, LinkPieces& out) {
  const Eigen::Vector3i n = grid_cells(extent, size);
  const auto at = [&](int axis, int i) { return -0.5 * extent[axis] + extent[axis] * i / n[axis]; };
  for (int i = 0; i < n[0]; ++i) {
    for (int j = 0; j < n[1]; ++j) {
      for (int k = 0; k < n[2]; ++k) {
        const Eigen::Vector3d lo(at(0, i), at(1, j), at(2, k)), hi(at(0, i + 1), at(1, j + 1), at(2, k + 1));
        if (!keep(lo, hi)) continue;
        for (int c = 0; c < 8; ++c) {
          out.corners.push_back(solid.pose * Eigen::Vector3d(c & 1 ? hi.x() : lo.x(), c & 2 ? hi.y() : lo.y(), c & 4 ? hi.z() : lo.z()));
        }
        out.close_piece();
      }
    }
  }
}

inline void add_solid(const Solid& solid, double size, LinkPieces& out) {
  const Eigen::AlignedBox3d bounds = solid.bounds();
  if (!bounds.min().allFinite() || !bounds.max().allFinite()) throw ParameterError("sphere cover: a collision solid is not finite");
  out.box.extend(bounds);
  switch (solid.kind) {
    case Solid::Kind::kMesh:
      add_mesh(solid, size, out);
      break;
    case Solid::Kind::kBox:  // FCL's primitives are solid: the whole volume
      add_cells(solid, solid.size, size, [](const auto&, const auto&) { return true; }, out);
      break;
    case Solid::Kind::kCylinder: {
      // Cells of the circumscribing box whose xy-rectangle comes within the radius of the axis.
      const double r = solid.radius;
      add_cells(solid, Eigen::Vector3d(2 * r, 2 * r, solid.length), size,
                [r](const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
                  const double x = std::clamp(0.0, lo.x(), hi.x()), y = std::clamp(0.0, lo.y(), hi.y());
                  return x * x + y * y <= r * r;
                },
                out);
      break;
    }
    case Solid::Kind::kSphere:
      out.balls.push_back({solid.pose.translation(), solid.radius});
      break;
  }
}

// How many pieces add_solid makes of `solids` at `size`, without making them: a triangle whose
// longest edge is L is split ceil(log2(L / size)) levels deep (each halves every edge), capped.
inline double piece_count(const std::vector<Solid>& solids, double size) {
  double n = 0.0;
  for (const Solid& s : solids) {
    if (s.kind == Solid::Kind::kSphere) continue;
    if (s.kind != Solid::Kind::kMesh) {
      n += static_cast<double>(kMaxCellsPerSolid);  // an upper bound is enough here
      continue;
    }
    const auto& v = s.mesh->vertices;
    for (const Eigen::Vector3i& t : s.mesh->triangles) {
      const Eigen::Vector3d &a = v[static_cast<std::size_t>(t[0])], &b = v[static_cast<std::size_t>(t[1])],
                            &c = v[static_cast<std::size_t>(t[2])];
      const double longest = std::sqrt(std::max({(a - b).squaredNorm(), (b - c).squaredNorm(), (c - a).squaredNorm()}));
      const double levels = longest <= size ? 0.0 : std::min<double>(kMaxSplitDepth, std::ceil(std::log2(longest / size)));
      n += std::pow(4.0, levels);
    }
  }
  return n;
}

inline LinkPieces cut_into_pieces(const std::vector<Solid>& solids, double size) {
  // Coarser only while that cuts the count: tiny triangles are one piece each at any size.
  for (double n = piece_count(solids, size); n > kMaxPiecesPerLink;) {
    const double coarser = piece_count(solids, size * kCoarser);
    if (coarser >= n) break;
    size *= kCoarser;
    n = coarser;
  }
  LinkPieces out;
  for (const Solid& s : solids) add_solid(s, size, out);
  return out;
}

}  // namespace amp::world::detail
