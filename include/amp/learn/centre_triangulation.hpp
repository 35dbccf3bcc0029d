#pragma once
#include <memory>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace amp::learn {

// The Delaunay triangulation of a set of 2-D centres named by small non-negative ids, kept up to
// date incrementally (CGAL's Delaunay_triangulation_2 with exact predicates): centres are inserted,
// moved (move_if_no_collision) and removed one at a time, never rebuilt. Its edges are the planning
// graph of Vlassis, Papakonstantinou & Tsanakas, "Learning the Voronoi centers of a mobile robot's
// configuration space" (section 4).
//
// Duplicates: a centre that coincides exactly with one already triangulated is kept out of the
// triangulation (it has no neighbours and no edges) until it moves apart or the centre it sits on
// moves away or is removed; then it is inserted. nearest() returns the triangulated one of such a
// pair. Collinear centres give the path of edges along their line (CGAL's 1-dimensional case).
class CentreTriangulation {
 public:
  CentreTriangulation();
  ~CentreTriangulation();
  CentreTriangulation(CentreTriangulation&&) noexcept;
  CentreTriangulation& operator=(CentreTriangulation&&) noexcept;

  // Throws std::invalid_argument when id is negative or already present.
  void insert(int id, const Eigen::Vector2d& p);
  // Moves a present centre (throws std::invalid_argument otherwise).
  void move(int id, const Eigen::Vector2d& p);
  // Removes a present centre (throws std::invalid_argument otherwise).
  void remove(int id);

  bool contains(int id) const;
  // True when the centre is present but kept out as a duplicate.
  bool hidden(int id) const;
  int size() const;  // centres present, hidden ones included
  // The ids joined to `id` by an edge, ascending, into `out` (cleared first).
  void neighbours(int id, std::vector<int>& out) const;
  // Every edge once as (smaller id, larger id), sorted.
  std::vector<std::pair<int, int>> edges() const;
  // The id of the triangulated centre nearest to p; -1 when there is none.
  int nearest(const Eigen::Vector2d& p) const;

 private:
  struct Impl;  // CGAL stays out of this header
  std::unique_ptr<Impl> impl_;
};

}  // namespace amp::learn
