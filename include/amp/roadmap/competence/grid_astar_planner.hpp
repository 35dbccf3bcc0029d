#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "amp/core/settings_schema.hpp"
#include "amp/core/space.hpp"
#include "amp/core/stop_condition.hpp"
#include "amp/roadmap/competence/grid_cell_table.hpp"
#include "amp/roadmap/competence/grid_chart.hpp"
#include "amp/roadmap/local_planners/local_planner.hpp"
#include "amp/world/validity_checker.hpp"

namespace amp::roadmap {

struct GridAStarSettings {
  int steps = 128;        // grid steps per degree of freedom across its range (512 for the puzzle: docs/run-cost-variance.md)
  int g_weight = 3;       // A in f = A g + B h
  int h_weight = 5;       // B: greedy, B > A
  // Cells checked per call before the search gives up whatever its competence; a safety net so
  // that an unlimited threshold cannot search 128^5 cells. Counted in the call's stats.
  std::size_t max_cells = 1000000;
  // steps, a (g_weight), b (h_weight), max_cells, as the competence PRMs take them.
  static const core::SettingsSchema<GridAStarSettings>& schema();
  void validate() const { schema().validate(*this); }  // throws ParameterError
};

// What one search did.
struct GridSearchStats {
  std::size_t cells_checked = 0;  // validity checks (CD calls) made
  std::size_t expanded = 0;       // F: cells expanded, roots excluded
  double competence = 0.0;        // largest O(C) = F / distance travelled seen
  bool abandoned = false;         // stopped by the threshold, max_cells or the run's stop, not by exhaustion
  bool capped = false;            // of which: by max_cells
  bool stopped = false;           // of which: by the run's stop condition (time limit or cancel)
  std::size_t path_cells = 0;     // cells on the path found (0 when none)
  std::size_t move_checks = 0;    // CD calls checking moves on the path at the space's resolution
  std::size_t repairs = 0;        // searches run again because a move clipped an obstacle
};

// Bidirectional A* on an implicit grid over the C-space (Isto 2003, docs/run-cost-variance.md): the grid is
// anchored at a; b's root is the cell nearest b (checked, unless it is a's cell). Moves change one
// coordinate by one step; g and h are Manhattan distances in cells, f = A g + B h, ties broken
// toward repeating the move that reached the cell, then toward the newest cell. A cell is checked
// once, when first reached; the two searches alternate and meet when one reaches a cell of the
// other. The path found is then checked move by move at the space's resolution (so that its edges
// are as valid as a straight-line planner's: cells alone can straddle a thin obstacle corner); a
// clipping move is forbidden and the search repeated. Both kinds of check are counted CD calls.
//
// Competence control: when a cell C is expanded, O(C) = F / (g(C) + g'), where F counts the cells
// expanded so far by both searches (C included, roots not) and g' is the depth of the other
// search's last expanded cell, i.e. cells examined per step travelled by both fronts; a straight
// free path has O = 1 throughout. The search is abandoned as soon as O > O_th.
//
// Memory and time are proportional to the cells reached: visited cells live in a GridCellTable
// (their ids index nodes_), nodes and heaps in vectors kept between calls.
//
// `stop`, when given, is polled every core::StopPoll::kStride CD calls of connect() (cells and move
// checks, counted across calls): once it fires the search is abandoned (stats.stopped) and the edge
// refused, and so is every later one before its first CD call. edge_waypoints() re-searches an
// accepted edge and is never stopped (it must find the same path).
class GridAStarPlanner final : public LocalPlanner {
 public:
  static constexpr int kMaxDims = GridCellTable::kMaxDims;

  // Throws ParameterError for bad settings or a space without a grid chart.
  GridAStarPlanner(const core::Space& space, const world::ValidityChecker& checker, GridAStarSettings settings = {},
                   const core::StopCondition* stop = nullptr);

  // O_th for the next calls; +infinity (the default) means no competence limit. Throws
  // ParameterError unless o_th > 0.
  void set_threshold(double o_th);
  double threshold() const { return threshold_; }

  bool connect(const State& a, const State& b) override;
  // Searches again without a threshold (same expansions, hence the same path as the accepted call)
  // and returns every grid state strictly between a and b. Costs CD calls like the first search;
  // keeping last_moves() of the accepted call and replay()ing them costs none.
  void edge_waypoints(const State& a, const State& b, const EdgeRequest& request, std::vector<State>& out) override;
  void edge_waypoints(const State& a, const State& b, std::vector<State>& out) { edge_waypoints(a, b, {}, out); }

  // The path of the last successful search as grid moves from a (one byte each: 2 * axis + (step > 0)).
  void last_moves(std::vector<std::uint8_t>& moves) const;
  // The states the moves visit from a (a excluded; b's cell dropped when it is b itself).
  void replay(const State& a, const State& b, const std::vector<std::uint8_t>& moves, std::vector<State>& out);

  const GridSearchStats& last() const { return last_; }
  const GridChart& chart() const { return chart_; }
  const GridAStarSettings& settings() const { return settings_; }

 private:
  using Cell = GridCellTable::Cell;
  struct Node {
    Cell cell;
    std::int32_t parent;
    std::int32_t g;
    std::int8_t side;  // 0 forward, 1 backward, kBlocked
    std::int8_t move;  // 2 * axis + (step > 0), -1 for a root
  };
  struct QueueEntry {
    std::uint64_t key;  // f, then tie, then newest first
    std::int32_t node;
  };
  static constexpr std::int8_t kBlocked = 2;

  bool search(const State& a, const State& b, double o_th);
  bool grid_search(double o_th);
  bool segment_free(const State& a, const State& b);
  std::size_t first_clipping_move();  // index in chain_ of the first bad move's end; 0 if none
  bool forbidden(const Cell& a, const Cell& b) const;
  std::int32_t insert(const Node& n);  // into nodes_ and cells_, same id
  bool cell_state(const Cell& c, State& out);
  int manhattan(const Cell& c, const Cell& target) const;
  void push(int side, std::int32_t node, int h);
  void trace(std::int32_t from_forward, std::int32_t from_backward);

  // Called once per CD call of the current search: true (and the stats marked) when the run's stop
  // condition says abandon it.
  bool must_stop();

  const core::Space* space_;
  const world::ValidityChecker* checker_;
  core::StopPoll poll_;      // counts CD calls across connect() calls, so short searches add up
  bool rechecking_ = false;  // inside edge_waypoints(): not stoppable
  GridAStarSettings settings_;
  GridChart chart_;
  int dims_;
  double threshold_ = std::numeric_limits<double>::infinity();
  GridSearchStats last_;

  std::vector<Node> nodes_;
  GridCellTable cells_;
  std::array<std::vector<QueueEntry>, 2> open_;
  std::uint64_t sequence_ = 0;
  std::array<double, kMaxDims> x_{};
  std::vector<std::int32_t> chain_;  // node ids of the last path found, a's cell to b's
  std::vector<std::uint8_t> moves_;
  Cell origin_{}, target_{};
  State target_state_;
  std::vector<std::pair<Cell, Cell>> forbidden_;  // moves found to clip an obstacle, this call
  State scratch_;
};

}  // namespace amp::roadmap
