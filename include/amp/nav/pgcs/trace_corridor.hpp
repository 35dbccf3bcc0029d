#pragma once
#include <cstdint>
#include <functional>
#include <vector>

#include <Eigen/Core>

#include "amp/nav/free_mask.hpp"

namespace amp::nav {

// Where the robot's centre has been, rasterised: the cells it passed through, each with a position it
// had there (a point known free for its disc). PGCS drives a route through the cells of the route's
// clusters along these known positions, instead of straight between the clusters' points: a
// Voronoi cell of a map of rooms often reaches round a wall, and a straight leg between two of its
// points then meets the wall, while the robot's own trace went round it.
//
// The searches reuse scratch buffers, so one corridor serves one thread (one PgcsSession).
class TraceCorridor {
 public:
  // The raster of `geometry` (its cells, origin and size; its free flags are not used).
  explicit TraceCorridor(const FreeMask& geometry);

  const FreeMask& geometry() const { return geometry_; }
  // Marks the cell holding p as visited (keeping the first position seen there); nothing outside.
  void visit(const Eigen::Vector2d& p);
  // Marks the cells segment a-b crosses, each with a point of the segment in it: the robot moved
  // straight from a to b, so every point between is a known-free position too (the cells of one
  // step join the previous step's side by side, not only corner to corner).
  void visit(const Eigen::Vector2d& a, const Eigen::Vector2d& b);
  // Unmarks every cell whose centre lies within `radius` of p: the world changed there (a door
  // closed), or the kept positions proved too close to an obstacle to drive between.
  void forget(const Eigen::Vector2d& p, double radius);
  bool visited(int cell) const { return cell >= 0 && first_[static_cast<std::size_t>(cell)].allFinite(); }
  std::size_t visited_count() const { return visited_; }
  // Changes with every cell marked or unmarked.
  std::uint64_t version() const { return version_; }

  // Waypoints from `from` to `to` (both included) through visited cells for which `allowed(cell)`
  // holds, and, round an end whose cell is not visited, any cell within `reach` of it (the ends
  // themselves are known free; the cells round them are the robot's guess, which a reach below the
  // thinnest wall cannot take through one): the octile-shortest cell path (A*, no corner cut), with
  // each cell replaced by its kept position, then shortened to the positions between which every
  // cell within one cell of the straight segment is passable on the same terms. Empty when no such
  // path joins them or an end is outside the raster.
  std::vector<Eigen::Vector2d> path(const Eigen::Vector2d& from, const Eigen::Vector2d& to, double reach,
                                    const std::function<bool(int)>& allowed) const;

  // Why no path joins a route: a flood from `from` through visited cells that admits the cells of
  // `labels` (label_of(cell): the cell's cluster) one label at a time, in route order, besides those
  // of `from_label` and the guessed cells round unvisited ends (as path() takes them); with each
  // label, widen(label, out) may append more labels to admit with it. Returns the index in `labels`
  // of the first one none of whose cells the flood reaches once admitted; labels.size() when each
  // is reached, and labels.size() + 1 when `to` is reached as well.
  std::size_t first_unreached(const Eigen::Vector2d& from, const Eigen::Vector2d& to, double reach, int from_label,
                              const std::vector<int>& labels, const std::function<int(int)>& label_of,
                              const std::function<void(int, std::vector<int>&)>& widen = {}) const;

 private:
  // Per-search scratch, valid for cells stamped with the current search.
  struct Ends {
    Eigen::Vector2d a, b;
    bool guess_a, guess_b;  // the end's cell is not visited: cells within reach of it are guessed
    double reach;
  };
  Ends ends(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double reach) const;
  bool guessed(int cell, const Ends& e) const;
  void new_search() const;
  // The cell's state in this search (zeroed the first time the search touches it).
  std::uint8_t& touch(int cell) const;
  // Whether every cell within one cell of segment a-b is passable.
  bool clear(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const std::function<bool(int)>& passable) const;
  // path()'s steps: the octile-shortest passable cell path from cell `from` to cell `to` (parent_
  // leads back from `to`), false when there is none; the cells' kept positions between the ends;
  // those positions shortened to the farthest each sees clear.
  bool cell_path(int from, int to, const std::function<bool(int)>& passable) const;
  std::vector<Eigen::Vector2d> kept_positions(int to_cell, const Eigen::Vector2d& from, const Eigen::Vector2d& to) const;
  std::vector<Eigen::Vector2d> shortened(const std::vector<Eigen::Vector2d>& points,
                                         const std::function<bool(int)>& passable) const;

  FreeMask geometry_;
  std::vector<Eigen::Vector2d> first_;  // per cell; NaN: not visited
  std::size_t visited_ = 0;
  std::uint64_t version_ = 0;
  mutable std::vector<std::uint32_t> stamp_;  // per cell: the search that last touched it
  mutable std::uint32_t search_ = 0;
  mutable std::vector<std::uint8_t> state_;   // per cell, this search: bit 0 passable known, 1 passable, 2 closed
  mutable std::vector<double> cost_;          // per cell, this search: cost from the start
  mutable std::vector<int> parent_, queue_;
  mutable std::vector<std::pair<double, int>> heap_;
};

}  // namespace amp::nav
