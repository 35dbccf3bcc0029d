#include "amp/roadmap/competence/grid_astar_planner.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include "amp/core/edge_steps.hpp"
#include "amp/core/error.hpp"

namespace amp::roadmap {

namespace {

// Offsets beyond this many cells from a are treated as blocked (cells are stored as int16).
constexpr int kMaxOffset = 32000;
constexpr int kMaxSteps = 16000;
// Searches run again after finding a path with a clipping move, before the call gives up.
constexpr int kMaxRepairs = 16;

bool later(std::uint64_t a, std::uint64_t b) { return a > b; }

}  // namespace

const core::SettingsSchema<GridAStarSettings>& GridAStarSettings::schema() {
  using S = GridAStarSettings;
  static const core::SettingsSchema<S> schema(
      "grid", {core::integer_field<S>("steps", &S::steps, 1, kMaxSteps, "A* grid steps per degree of freedom"),
               core::integer_field<S>("a", &S::g_weight, 0, 1000, "A in f = A g + B h"),
               core::integer_field<S>("b", &S::h_weight, 1, 1000, "B in f = A g + B h"),
               core::integer_field<S>("max_cells", &S::max_cells, 1, 1e9,
                                      "cells checked per A* call before it gives up regardless of O_th")});
  return schema;
}

GridAStarPlanner::GridAStarPlanner(const core::Space& space, const world::ValidityChecker& checker,
                                   GridAStarSettings settings, const core::StopCondition* stop)
    : space_(&space),
      checker_(&checker),
      poll_(stop),
      settings_(settings),
      chart_(space, settings.steps),
      dims_(chart_.dimension()),
      cells_(std::min(dims_, kMaxDims)) {
  settings_.validate();
  if (dims_ > kMaxDims) {
    throw ParameterError("grid: at most " + std::to_string(kMaxDims) + " degrees of freedom, got " + std::to_string(dims_));
  }
}

void GridAStarPlanner::set_threshold(double o_th) {
  if (!(o_th > 0.0)) throw ParameterError("grid: the competence threshold O_th must be > 0");
  threshold_ = o_th;
}

bool GridAStarPlanner::connect(const State& a, const State& b) {
  bool ok = false;
  if (poll_.fired()) {
    last_ = GridSearchStats{};
    chain_.clear();
    last_.abandoned = last_.stopped = true;
  } else {
    ok = search(a, b, threshold_);
  }
  checker_->counters().add_local_plan(ok);
  return ok;
}

void GridAStarPlanner::edge_waypoints(const State& a, const State& b, const EdgeRequest&, std::vector<State>& out) {
  rechecking_ = true;
  const bool found = search(a, b, std::numeric_limits<double>::infinity());
  rechecking_ = false;
  if (!found) throw Error("grid A*: an accepted edge could not be searched again");
  last_moves(moves_);
  replay(a, b, moves_, out);
}

void GridAStarPlanner::last_moves(std::vector<std::uint8_t>& moves) const {
  moves.clear();
  for (std::size_t i = 1; i < chain_.size(); ++i) {
    const Cell& p = nodes_[static_cast<std::size_t>(chain_[i - 1])].cell;
    const Cell& c = nodes_[static_cast<std::size_t>(chain_[i])].cell;
    for (int axis = 0; axis < dims_; ++axis) {
      const auto u = static_cast<std::size_t>(axis);
      if (c[u] != p[u]) moves.push_back(static_cast<std::uint8_t>(2 * axis + (c[u] > p[u] ? 1 : 0)));
    }
  }
}

void GridAStarPlanner::replay(const State& a, const State& b, const std::vector<std::uint8_t>& moves,
                              std::vector<State>& out) {
  out.clear();
  chart_.set_origin(a);
  Cell c{};
  for (const std::uint8_t m : moves) {
    const auto axis = static_cast<std::size_t>(m / 2);
    c[axis] = static_cast<std::int16_t>(c[axis] + ((m % 2) ? 1 : -1));
    State s;
    cell_state(c, s);
    out.push_back(s);
  }
  // The root cell of b is its own state only when b lies on the grid.
  if (!out.empty() && space_->distance(out.back(), b) == 0.0) out.pop_back();
}

std::int32_t GridAStarPlanner::insert(const Node& n) {
  nodes_.push_back(n);
  return cells_.insert(n.cell);
}

bool GridAStarPlanner::cell_state(const Cell& c, State& out) {
  for (int i = 0; i < dims_; ++i) {
    const auto u = static_cast<std::size_t>(i);
    if (std::abs(c[u]) > kMaxOffset) return false;
    x_[u] = c[u] * chart_.step(i);
  }
  return chart_.state_at(x_.data(), out);
}

int GridAStarPlanner::manhattan(const Cell& c, const Cell& target) const {
  int h = 0;
  for (int i = 0; i < dims_; ++i) h += std::abs(c[static_cast<std::size_t>(i)] - target[static_cast<std::size_t>(i)]);
  return h;
}

void GridAStarPlanner::push(int side, std::int32_t node, int h) {
  const Node& n = nodes_[static_cast<std::size_t>(node)];
  const Node& parent = nodes_[static_cast<std::size_t>(n.parent)];
  const std::uint64_t f = static_cast<std::uint64_t>(settings_.g_weight) * static_cast<std::uint64_t>(n.g) +
                          static_cast<std::uint64_t>(settings_.h_weight) * static_cast<std::uint64_t>(h);
  const std::uint64_t tie = n.move == parent.move ? 0 : 1;  // prefer repeating the last joint move
  const std::uint64_t newest = 0xffffffffULL - (sequence_++ & 0xffffffffULL);
  auto& heap = open_[static_cast<std::size_t>(side)];
  heap.push_back(QueueEntry{(f << 33) | (tie << 32) | newest, node});
  std::push_heap(heap.begin(), heap.end(), [](const QueueEntry& x, const QueueEntry& y) { return later(x.key, y.key); });
}

bool GridAStarPlanner::search(const State& a, const State& b, double o_th) {
  last_ = GridSearchStats{};
  chain_.clear();
  forbidden_.clear();
  chart_.set_origin(a);
  chart_.coordinates(b, x_.data());
  origin_ = Cell{};
  for (int i = 0; i < dims_; ++i) {
    const double t = std::round(x_[static_cast<std::size_t>(i)] / chart_.step(i));
    if (std::abs(t) > kMaxOffset) return false;
    target_[static_cast<std::size_t>(i)] = static_cast<std::int16_t>(t);
  }
  if (target_ == origin_) {  // b lies within half a cell of a: the one hop a -> b
    last_.path_cells = 1;
    return segment_free(a, b);
  }
  // O(C) >= 1 for every expanded cell (its g ancestors and the other front's g' cells were
  // expanded first), so below 1 only b's cell next to a's can be reached: skip a doomed search.
  if (o_th < 1.0 && manhattan(target_, origin_) > 1) {
    last_.abandoned = true;
    return false;
  }
  // b's root: the cell nearest b, which must itself be free (b is within half a step of it), as
  // must the hop between them.
  if (!cell_state(target_, target_state_)) return false;
  if (must_stop()) return false;
  ++last_.cells_checked;
  if (!checker_->is_valid(target_state_) || !segment_free(target_state_, b)) return false;

  // The search checks cells; the path it finds is then checked move by move at the space's
  // resolution, as a straight-line edge would be. A move that clips an obstacle between two free
  // cells is forbidden and the search run again (rare: thin obstacle corners).
  for (int attempt = 0; attempt <= kMaxRepairs; ++attempt) {
    if (!grid_search(o_th)) return false;
    const std::size_t bad = first_clipping_move();
    if (last_.stopped) {  // the move checks were cut short: no verdict on the path
      chain_.clear();
      return false;
    }
    if (bad == 0) return true;
    ++last_.repairs;
    forbidden_.emplace_back(nodes_[static_cast<std::size_t>(chain_[bad - 1])].cell,
                            nodes_[static_cast<std::size_t>(chain_[bad])].cell);
    chain_.clear();
  }
  last_.abandoned = true;
  return false;
}

bool GridAStarPlanner::must_stop() {
  if (rechecking_ || !poll_.step()) return false;
  last_.abandoned = last_.stopped = true;
  return true;
}

bool GridAStarPlanner::segment_free(const State& a, const State& b) {
  const std::int64_t segments = core::edge_segments(space_->distance(a, b), space_->resolution());
  if (segments == 0) return false;  // too many steps to count: refused, as a straight edge would be
  const double n = static_cast<double>(segments);
  for (std::int64_t j = 1; j < segments; ++j) {
    space_->interpolate(a, b, static_cast<double>(j) / n, scratch_);
    if (must_stop()) return false;
    ++last_.move_checks;
    if (!checker_->is_valid(scratch_)) return false;
  }
  return true;
}

std::size_t GridAStarPlanner::first_clipping_move() {
  State from, to;
  cell_state(nodes_[static_cast<std::size_t>(chain_[0])].cell, from);
  for (std::size_t i = 1; i < chain_.size(); ++i) {
    cell_state(nodes_[static_cast<std::size_t>(chain_[i])].cell, to);
    if (!segment_free(from, to)) return i;
    from = to;
  }
  return 0;
}

bool GridAStarPlanner::forbidden(const Cell& a, const Cell& b) const {
  for (const auto& [x, y] : forbidden_) {
    if ((x == a && y == b) || (x == b && y == a)) return true;
  }
  return false;
}

bool GridAStarPlanner::grid_search(double o_th) {
  nodes_.clear();
  cells_.clear();
  sequence_ = 0;
  open_[0].clear();
  open_[1].clear();
  last_.expanded = 0;

  insert(Node{origin_, 0, 0, 0, -1});
  insert(Node{target_, 1, 0, 1, -1});
  nodes_[0].parent = 0;
  const auto less_urgent = [](const QueueEntry& x, const QueueEntry& y) { return later(x.key, y.key); };
  open_[0].push_back(QueueEntry{0, 0});
  open_[1].push_back(QueueEntry{0, 1});
  std::array<std::int32_t, 2> last_depth{0, 0};
  const std::array<const Cell*, 2> goal_of{&target_, &origin_};

  for (int side = 0;; side = 1 - side) {
    auto& heap = open_[static_cast<std::size_t>(side)];
    if (heap.empty()) return false;  // this front is enclosed: no grid path
    std::pop_heap(heap.begin(), heap.end(), less_urgent);
    const std::int32_t current = heap.back().node;
    heap.pop_back();
    const Node c = nodes_[static_cast<std::size_t>(current)];  // a copy: insert() may reallocate
    if (c.g > 0) {
      ++last_.expanded;
      const double o = static_cast<double>(last_.expanded) / static_cast<double>(c.g + last_depth[static_cast<std::size_t>(1 - side)]);
      last_.competence = std::max(last_.competence, o);
      if (o > o_th) {
        last_.abandoned = true;
        return false;
      }
    }
    last_depth[static_cast<std::size_t>(side)] = c.g;
    for (int axis = 0; axis < dims_; ++axis) {
      for (int dir = 0; dir < 2; ++dir) {
        Cell n = c.cell;
        n[static_cast<std::size_t>(axis)] = static_cast<std::int16_t>(n[static_cast<std::size_t>(axis)] + (dir ? 1 : -1));
        if (!forbidden_.empty() && forbidden(c.cell, n)) continue;
        const std::int32_t seen = cells_.find(n);
        if (seen >= 0) {
          const Node& other = nodes_[static_cast<std::size_t>(seen)];
          if (other.side == 1 - side) {  // the fronts meet
            trace(side == 0 ? current : seen, side == 0 ? seen : current);
            last_.path_cells = static_cast<std::size_t>(c.g + other.g + 2);
            return true;
          }
          continue;  // blocked, or already reached by this front
        }
        const auto move = static_cast<std::int8_t>(2 * axis + dir);
        if (!cell_state(n, scratch_)) {  // outside the bounds: blocked, and not a CD call
          insert(Node{n, current, c.g + 1, kBlocked, move});
          continue;
        }
        if (last_.cells_checked >= settings_.max_cells) {
          last_.abandoned = true;
          last_.capped = true;
          return false;
        }
        if (must_stop()) return false;
        ++last_.cells_checked;
        const bool free = checker_->is_valid(scratch_);
        const std::int32_t id = insert(Node{n, current, c.g + 1, free ? static_cast<std::int8_t>(side) : kBlocked, move});
        if (free) push(side, id, manhattan(n, *goal_of[static_cast<std::size_t>(side)]));
      }
    }
  }
}

void GridAStarPlanner::trace(std::int32_t from_forward, std::int32_t from_backward) {
  chain_.clear();
  for (std::int32_t v = from_forward; v != 0; v = nodes_[static_cast<std::size_t>(v)].parent) chain_.push_back(v);
  chain_.push_back(0);
  std::reverse(chain_.begin(), chain_.end());
  for (std::int32_t v = from_backward;; v = nodes_[static_cast<std::size_t>(v)].parent) {
    chain_.push_back(v);
    if (v == 1) break;
  }
}

}  // namespace amp::roadmap
