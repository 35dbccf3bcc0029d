#include "amp/nav/pgcs/trace_corridor.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "amp/world/polygon_geometry.hpp"

namespace amp::nav {

namespace {

const Eigen::Vector2d kUnvisited = Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN());

// How far ahead the shortening looks for a straight stretch, in path cells: it bounds the work per
// waypoint (a stretch longer than this is cut into pieces, which costs nothing in length).
constexpr std::size_t kMaxStretch = 64;

// A shortened leg keeps every cell whose centre lies within this many cells of it passable: it may
// pass the corner of an unknown cell, never near its middle. (MovingAI rooms and the office map,
// seed 1: a band of 1 cell gave paths 1.11x and 1.27x the shortest, half a cell 1.09x and 1.13x.)
constexpr double kClearBand = 0.5;

constexpr std::uint8_t kKnown = 1, kPassable = 2, kClosed = 4, kReached = 8, kWaiting = 16;

}  // namespace

TraceCorridor::TraceCorridor(const FreeMask& geometry)
    : geometry_(geometry.width(), geometry.height(), geometry.cell_size(), geometry.origin()),
      first_(geometry.cell_count(), kUnvisited),
      stamp_(geometry.cell_count(), 0),
      state_(geometry.cell_count(), 0),
      cost_(geometry.cell_count(), 0.0),
      parent_(geometry.cell_count(), -1) {}

void TraceCorridor::visit(const Eigen::Vector2d& p) {
  const int cell = geometry_.cell_of(p);
  if (cell < 0) return;
  Eigen::Vector2d& f = first_[static_cast<std::size_t>(cell)];
  if (f.allFinite()) return;
  f = p;
  ++visited_;
  ++version_;
}

void TraceCorridor::visit(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  // Samples an eighth of a cell apart: a cell the segment crosses for less than that (a corner
  // clipped) may be missed, and its two neighbours then meet corner to corner only.
  const double length = (b - a).norm();
  const int n = static_cast<int>(std::ceil(length / (geometry_.cell_size() / 8.0)));
  for (int i = 0; i <= n; ++i) visit(n == 0 ? b : Eigen::Vector2d(a + (b - a) * (static_cast<double>(i) / n)));
}

void TraceCorridor::forget(const Eigen::Vector2d& p, double radius) {
  const double cs = geometry_.cell_size();
  const Eigen::Vector2d lo = (p - geometry_.origin()).array() / cs - radius / cs;
  const Eigen::Vector2d hi = (p - geometry_.origin()).array() / cs + radius / cs;
  const int x0 = std::max(0, static_cast<int>(std::floor(lo.x()))), x1 = std::min(geometry_.width() - 1, static_cast<int>(hi.x()));
  const int y0 = std::max(0, static_cast<int>(std::floor(lo.y()))), y1 = std::min(geometry_.height() - 1, static_cast<int>(hi.y()));
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const auto cell = static_cast<std::size_t>(geometry_.index(x, y));
      if (first_[cell].allFinite() && (geometry_.cell_center(x, y) - p).norm() <= radius) {
        first_[cell] = kUnvisited;
        --visited_;
        ++version_;
      }
    }
  }
}

void TraceCorridor::new_search() const {
  if (++search_ == 0) {  // wrapped: no stamp may look current
    std::fill(stamp_.begin(), stamp_.end(), 0);
    search_ = 1;
  }
}

std::uint8_t& TraceCorridor::touch(int cell) const {
  const auto c = static_cast<std::size_t>(cell);
  if (stamp_[c] != search_) stamp_[c] = search_, state_[c] = 0;
  return state_[c];
}

TraceCorridor::Ends TraceCorridor::ends(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double reach) const {
  return {a, b, !visited(geometry_.cell_of(a)), !visited(geometry_.cell_of(b)), reach};
}

bool TraceCorridor::guessed(int cell, const Ends& e) const {
  const Eigen::Vector2d c = geometry_.cell_center(cell);
  return (e.guess_a && (c - e.a).norm() <= e.reach) || (e.guess_b && (c - e.b).norm() <= e.reach);
}

bool TraceCorridor::clear(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                          const std::function<bool(int)>& passable) const {
  const double cs = geometry_.cell_size();
  const Eigen::Vector2d lo = (a.cwiseMin(b) - geometry_.origin()).array() / cs - 1.0;
  const Eigen::Vector2d hi = (a.cwiseMax(b) - geometry_.origin()).array() / cs + 1.0;
  const int x0 = std::max(0, static_cast<int>(std::floor(lo.x()))), x1 = std::min(geometry_.width() - 1, static_cast<int>(hi.x()));
  const int y0 = std::max(0, static_cast<int>(std::floor(lo.y()))), y1 = std::min(geometry_.height() - 1, static_cast<int>(hi.y()));
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      if (std::sqrt(world::point_segment_distance_sq(geometry_.cell_center(x, y), a, b)) <= kClearBand * cs && !passable(geometry_.index(x, y))) {
        return false;
      }
    }
  }
  return true;
}

std::vector<Eigen::Vector2d> TraceCorridor::path(const Eigen::Vector2d& from, const Eigen::Vector2d& to, double reach,
                                                 const std::function<bool(int)>& allowed) const {
  const int ca = geometry_.cell_of(from), cb = geometry_.cell_of(to);
  if (ca < 0 || cb < 0) return {};
  if (ca == cb) return {from, to};
  const Ends e = ends(from, to, reach);
  new_search();
  // Asked once per cell and search: `allowed` may cost a nearest-centre query.
  const std::function<bool(int)> passable = [&](int cell) {
    std::uint8_t& s = touch(cell);
    if ((s & kKnown) == 0) {
      const bool p = cell == ca || cell == cb || (visited(cell) && allowed(cell)) || guessed(cell, e);
      s |= kKnown | (p ? kPassable : 0);
    }
    return (s & kPassable) != 0;
  };
  if (!cell_path(ca, cb, passable)) return {};
  return shortened(kept_positions(cb, from, to), passable);
}

bool TraceCorridor::cell_path(int from, int to, const std::function<bool(int)>& passable) const {
  // A* over the cells, octile steps, a diagonal only between two passable side cells.
  const double cs = geometry_.cell_size();
  const int bx = to % geometry_.width(), by = to / geometry_.width();
  const auto h = [&](int cell) {
    const double dx = std::abs(cell % geometry_.width() - bx), dy = std::abs(cell / geometry_.width() - by);
    return cs * (std::max(dx, dy) + (std::numbers::sqrt2 - 1.0) * std::min(dx, dy));
  };
  heap_.clear();
  const auto push = [&](double f, int cell) {
    heap_.emplace_back(-f, cell);
    std::push_heap(heap_.begin(), heap_.end());
  };
  touch(from);
  cost_[static_cast<std::size_t>(from)] = 0.0;
  parent_[static_cast<std::size_t>(from)] = -1;
  state_[static_cast<std::size_t>(from)] |= kReached;
  push(h(from), from);
  while (!heap_.empty()) {
    std::pop_heap(heap_.begin(), heap_.end());
    const int c = heap_.back().second;
    heap_.pop_back();
    std::uint8_t& sc = touch(c);
    if ((sc & kClosed) != 0) continue;
    sc |= kClosed;
    if (c == to) return true;
    const int x = c % geometry_.width(), y = c / geometry_.width();
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        if ((dx == 0 && dy == 0) || !geometry_.contains(x + dx, y + dy)) continue;
        const int n = geometry_.index(x + dx, y + dy);
        if (!passable(n)) continue;
        if (dx != 0 && dy != 0 && !(passable(geometry_.index(x + dx, y)) && passable(geometry_.index(x, y + dy)))) continue;
        const double g = cost_[static_cast<std::size_t>(c)] + (dx != 0 && dy != 0 ? std::numbers::sqrt2 * cs : cs);
        std::uint8_t& sn = touch(n);
        if ((sn & kClosed) != 0) continue;
        if ((sn & kReached) != 0 && cost_[static_cast<std::size_t>(n)] <= g) continue;
        sn |= kReached;
        cost_[static_cast<std::size_t>(n)] = g;
        parent_[static_cast<std::size_t>(n)] = c;
        push(g + h(n), n);
      }
    }
  }
  return false;
}

std::vector<Eigen::Vector2d> TraceCorridor::kept_positions(int to_cell, const Eigen::Vector2d& from,
                                                           const Eigen::Vector2d& to) const {
  std::vector<int> cells;
  for (int c = to_cell; c >= 0; c = parent_[static_cast<std::size_t>(c)]) cells.push_back(c);
  std::reverse(cells.begin(), cells.end());
  std::vector<Eigen::Vector2d> points;
  points.reserve(cells.size());
  points.push_back(from);
  for (std::size_t i = 1; i + 1 < cells.size(); ++i) {
    const auto c = static_cast<std::size_t>(cells[i]);
    points.push_back(first_[c].allFinite() ? first_[c] : geometry_.cell_center(cells[i]));
  }
  points.push_back(to);
  return points;
}

std::vector<Eigen::Vector2d> TraceCorridor::shortened(const std::vector<Eigen::Vector2d>& points,
                                                      const std::function<bool(int)>& passable) const {
  // From each kept point, on to the farthest point ahead that it sees clear.
  std::vector<Eigen::Vector2d> out{points.front()};
  std::size_t i = 0;
  while (i + 1 < points.size()) {
    std::size_t next = i + 1;
    for (std::size_t k = i + 2; k < points.size() && k <= i + kMaxStretch; ++k) {
      if (!clear(points[i], points[k], passable)) break;
      next = k;
    }
    out.push_back(points[next]);
    i = next;
  }
  return out;
}

std::size_t TraceCorridor::first_unreached(const Eigen::Vector2d& from, const Eigen::Vector2d& to, double reach,
                                           int from_label, const std::vector<int>& labels,
                                           const std::function<int(int)>& label_of,
                                           const std::function<void(int, std::vector<int>&)>& widen) const {
  const int start = geometry_.cell_of(from), goal = geometry_.cell_of(to);
  if (start < 0) return 0;
  const Ends e = ends(from, to, reach);
  new_search();
  std::vector<int> admitted, waiting, reached_labels;
  std::vector<std::uint8_t> in;  // by label: admitted
  const auto admit = [&](int label) {
    const std::size_t from = admitted.size();
    admitted.push_back(label);
    if (widen) widen(label, admitted);
    for (std::size_t j = from; j < admitted.size(); ++j) {
      if (admitted[j] < 0) continue;
      const auto l = static_cast<std::size_t>(admitted[j]);
      if (l >= in.size()) in.resize(l + 1, 0);
      in[l] = 1;
    }
  };
  const auto admits = [&](int cell) {
    if (cell == start || cell == goal || guessed(cell, e)) return true;
    if (!visited(cell)) return false;
    const int k = label_of(cell);
    return k >= 0 && static_cast<std::size_t>(k) < in.size() && in[static_cast<std::size_t>(k)] != 0;
  };
  admit(from_label);
  const auto reach_cell = [&](int cell) {
    touch(cell) = kReached;
    queue_.push_back(cell);
    if (visited(cell)) reached_labels.push_back(label_of(cell));
  };
  const auto flood = [&] {
    while (!queue_.empty()) {
      const int c = queue_.back();
      queue_.pop_back();
      const int x = c % geometry_.width(), y = c / geometry_.width();
      const int nx[4] = {x + 1, x - 1, x, x}, ny[4] = {y, y, y + 1, y - 1};
      for (int i = 0; i < 4; ++i) {
        if (!geometry_.contains(nx[i], ny[i])) continue;
        const int n = geometry_.index(nx[i], ny[i]);
        std::uint8_t& s = touch(n);
        if ((s & (kReached | kWaiting)) != 0) continue;
        if (admits(n)) {
          reach_cell(n);
        } else if (visited(n)) {
          s = kWaiting;  // beside the flood, not admitted (yet)
          waiting.push_back(n);
        }
      }
    }
  };
  queue_.clear();
  reach_cell(start);
  flood();
  for (std::size_t i = 0; i < labels.size(); ++i) {
    admit(labels[i]);
    for (int c : waiting) {
      if (touch(c) == kWaiting && admits(c)) reach_cell(c);
    }
    flood();
    if (std::find(reached_labels.begin(), reached_labels.end(), labels[i]) == reached_labels.end()) return i;
  }
  return goal >= 0 && touch(goal) == kReached ? labels.size() + 1 : labels.size();
}

}  // namespace amp::nav
