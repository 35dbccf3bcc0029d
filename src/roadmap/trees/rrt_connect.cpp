#include "amp/roadmap/trees/rrt_connect.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "amp/core/error.hpp"
#include "amp/roadmap/local_planners/edge_certifier.hpp"
#include "amp/roadmap/neighbors/kd_tree_neighbors.hpp"
#include "amp/roadmap/local_planners/straight_line_planner.hpp"

namespace amp::roadmap {

namespace {
// Trees of a failed leg up to this size are copied into the result's roadmap for drawing (~10 ms).
constexpr std::size_t kMaxCopiedFailedTrees = 5000;
}  // namespace

namespace {

// First reservation per tree; trees grow beyond it by doubling (a node limit of 10^9 must not
// reserve 10^9 states, and most legs end long before their budget).
constexpr std::size_t kInitialReserve = 1 << 14;
constexpr std::size_t kNoNode = std::numeric_limits<std::size_t>::max();
constexpr double kMaxRange = 1e12;

// One tree of a leg: states stored contiguously with their parent links (a parent always precedes
// its children), whether each node's edge to its parent is certified, and an exact KD-tree over the
// states for the nearest node.
class Tree {
 public:
  Tree(const core::Space& space, core::Counters& counters, std::size_t reserve)
      : space_(&space), counters_(&counters), reserve_(reserve) {
    states_.reserve(reserve);
    parents_.reserve(reserve);
    certified_.reserve(reserve);
    neighbors_.reserve(1);
  }

  void reset(const State& root) {
    states_.clear();
    parents_.clear();
    certified_.clear();
    rebuild_index();
    add(root, kNoNode, true);
  }

  std::size_t add(const State& s, std::size_t parent, bool certified) {
    const std::size_t id = states_.size();
    states_.push_back(s);
    parents_.push_back(parent);
    certified_.push_back(certified ? 1 : 0);
    nn_->add(id, s);
    return id;
  }

  Neighbor nearest(const State& q) const {
    nn_->k_nearest(q, 1, neighbors_);
    return neighbors_.front();
  }

  // Removes `child` (not the root) and every node below it; the survivors keep their order, so
  // parents still precede children. KdTreeNeighbors cannot delete: it is rebuilt from the survivors.
  // Returns how many nodes left.
  std::size_t cut(std::size_t child) {
    const std::size_t n = states_.size();
    removed_.assign(n, 0);
    removed_[child] = 1;
    for (std::size_t i = child + 1; i < n; ++i) removed_[i] = removed_[parents_[i]];
    remap_.assign(n, kNoNode);
    std::size_t kept = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (removed_[i] != 0) continue;
      remap_[i] = kept;
      states_[kept] = states_[i];
      parents_[kept] = parents_[i] == kNoNode ? kNoNode : remap_[parents_[i]];
      certified_[kept] = certified_[i];
      ++kept;
    }
    states_.resize(kept);
    parents_.resize(kept);
    certified_.resize(kept);
    rebuild_index();
    for (std::size_t i = 0; i < kept; ++i) nn_->add(i, states_[i]);
    return n - kept;
  }

  std::size_t size() const { return states_.size(); }
  const State& state(std::size_t i) const { return states_[i]; }
  std::size_t parent(std::size_t i) const { return parents_[i]; }
  bool certified(std::size_t i) const { return certified_[i] != 0; }
  void set_certified(std::size_t i) { certified_[i] = 1; }

 private:
  void rebuild_index() {
    nn_ = std::make_unique<KdTreeNeighbors>(*space_, counters_);
    nn_->reserve(std::max(reserve_, states_.size()));
  }

  const core::Space* space_;
  core::Counters* counters_;
  std::size_t reserve_;
  std::vector<State> states_;
  std::vector<std::size_t> parents_;
  std::vector<std::uint8_t> certified_;
  std::unique_ptr<KdTreeNeighbors> nn_;
  mutable std::vector<Neighbor> neighbors_;
  std::vector<std::uint8_t> removed_;  // cut() scratch
  std::vector<std::size_t> remap_;
};

// Where a leg's trees met: the meeting edge joins start-tree node `start` to goal-tree node `goal`.
struct Meeting {
  std::size_t start = kNoNode;
  std::size_t goal = kNoNode;
};

enum class Growth { kTrapped, kAdvanced, kReached };  // Kuffner & LaValle, Fig. 2's EXTEND results

// One RRT-Connect run: the current leg's two trees (0 grows from the leg's first seed, 1 from its
// second) and the forest of every leg tried, for the result.
class RrtConnectRun {
 public:
  RrtConnectRun(double range, const PlanningContext& ctx, const core::StopCondition& stop)
      : ctx_(ctx),
        stop_(stop),
        range_(range),
        certified_mode_(ctx.edge_check == core::EdgeCheckMode::kCertified),
        local_planner_(ctx.space, ctx.checker, &stop),
        certifier_(ctx.space, ctx.checker, &stop),
        trees_{Tree(ctx.space, ctx.checker.counters(), std::min(stop.node_limit(), kInitialReserve)),
               Tree(ctx.space, ctx.checker.counters(), std::min(stop.node_limit(), kInitialReserve))},
        forest_(std::make_shared<Roadmap>()) {}

  PlanResult run(core::Rng& rng) {
    PlanResult result;
    const std::vector<State>& seeds = ctx_.seeds;
    result.status = core::PlanStatus::kSolved;
    if (seeds.size() == 1) {  // nothing to connect
      goal_root_ = forest_->add_vertex(seeds.front());
      result.path = seeds;
    }
    for (leg_ = 0; leg_ + 1 < seeds.size(); ++leg_) {
      trees_[0].reset(seeds[leg_]);
      trees_[1].reset(seeds[leg_ + 1]);
      Meeting m;
      const bool solved = solve_leg(rng, m);
      if (solved) append_leg_path(m, result.path);
      if (!solved) {
        result.status = status_for(reason_);
        result.path.clear();
        stop_leg_trees();
        break;
      }
      append_forest(&m);
      ++legs_solved_;
    }
    result.nodes = forest_->vertex_count() + uncopied_.nodes;
    result.edges = forest_->edge_count() + uncopied_.edges;
    result.components = forest_->component_count() + uncopied_.components;
    result.extra["range"] = range_;
    result.extra["legs_solved"] = static_cast<double>(legs_solved_);
    result.extra["certify_refused"] = static_cast<double>(certify_refused_);
    result.extra["nodes_cut"] = static_cast<double>(nodes_cut_);
    certifier_.report(result.extra);
    result.roadmap = forest_;
    return result;
  }

 private:
  // Live nodes: finished legs (in the forest) plus the current trees; the leg's first seed is the
  // previous leg's goal root, counted once.
  std::size_t nodes() const { return forest_->vertex_count() + trees_[0].size() + trees_[1].size() - (leg_ > 0 ? 1 : 0); }

  bool stopped() {
    reason_ = stop_.check(nodes());
    return reason_ != core::StopReason::kNone;
  }

  // Kuffner & LaValle's main loop (Fig. 5, RRT_CONNECT_PLANNER): EXTEND one tree towards a random
  // state; if it moved, CONNECT the other tree to the new node; swap the trees' roles.
  bool solve_leg(core::Rng& rng, Meeting& m) {
    int side = 0;
    for (;;) {
      if (stopped()) return false;
      ctx_.space.sample_uniform(rng, sample_);  // uniform, no goal bias (as OMPL's RRTConnect)
      std::size_t added = kNoNode;
      if (grow(side, sample_, false, added) != Growth::kTrapped) {
        if (connect(1 - side, added, m)) {
          if (certify_path(m)) return true;
        } else if (reason_ != core::StopReason::kNone) {
          return false;
        }
      }
      side = 1 - side;
    }
  }

  // CONNECT (Fig. 5): EXTEND tree `side` towards node `target` of the other tree until it reaches it
  // (the meeting edge, which is not added to either tree) or is trapped. Polls the stop condition
  // before each step so that a node limit is never overshot.
  bool connect(int side, std::size_t target, Meeting& m) {
    const State& q = trees_[1 - side].state(target);
    for (;;) {
      if (stopped()) return false;
      std::size_t node = kNoNode;
      const Growth g = grow(side, q, true, node);
      if (g == Growth::kTrapped) return false;
      if (g == Growth::kReached) {
        m = side == 0 ? Meeting{node, target} : Meeting{target, node};
        return true;
      }
    }
  }

  // EXTEND (Fig. 2) tree `side` by one step of at most range_ from its nearest node towards q. A
  // sample within range is added itself (kReached). A target that is a node of the other tree
  // (`q_is_node`, valid already) is not added: kReached then returns the nearest node in `node`,
  // the end of the meeting edge.
  Growth grow(int side, const State& q, bool q_is_node, std::size_t& node) {
    Tree& tree = trees_[side];
    const Neighbor near = tree.nearest(q);
    const State& from = tree.state(near.index);
    if (near.distance <= range_ && q_is_node) {
      if (!edge_free(side, from, q)) return Growth::kTrapped;
      node = near.index;
      return Growth::kReached;
    }
    const bool reach = near.distance <= range_;
    if (!reach) {
      ctx_.space.interpolate(from, q, range_ / near.distance, step_);
      // Interpolation that makes no progress would loop forever (OMPL's growTree guards the same).
      if (ctx_.space.distance(from, step_) == 0.0) return Growth::kTrapped;
    }
    const State& to = reach ? q : step_;
    if (!ctx_.checker.is_valid(to) || !edge_free(side, from, to)) return Growth::kTrapped;
    node = tree.add(to, near.index, certified_mode_);
    return reach ? Growth::kReached : Growth::kAdvanced;
  }

  // The edge from tree node `from` to `to`, checked in the path's direction (start side -> goal
  // side) as OMPL's RRTConnect does; certified mode proves it free instead of sampling it. Both
  // checks poll the stop condition and refuse the edge once it fires; the next stopped() reports it.
  bool edge_free(int side, const State& from, const State& to) {
    const State& a = side == 0 ? from : to;
    const State& b = side == 0 ? to : from;
    return certified_mode_ ? certifier_.certify(a, b) : local_planner_.connect(a, b);
  }

  // Certifies the candidate path's edges not yet certified (none left in certified mode), walking
  // each tree from its root to the meeting node so that the refusal nearest the root, which cuts
  // the most, is found first. A refused tree edge is cut with its subtree; the meeting edge, refused,
  // is simply not made. False when anything was refused: the search goes on.
  bool certify_path(const Meeting& m) {
    if (certified_mode_) return true;
    bool whole = true;
    for (int side = 0; side < 2; ++side) {
      chain_.clear();
      for (std::size_t v = side == 0 ? m.start : m.goal; v != kNoNode; v = trees_[side].parent(v)) chain_.push_back(v);
      Tree& tree = trees_[side];
      for (auto it = chain_.rbegin(); it != chain_.rend(); ++it) {
        const std::size_t child = *it;
        if (tree.certified(child)) continue;
        const State& parent = tree.state(tree.parent(child));
        const State& a = side == 0 ? parent : tree.state(child);
        const State& b = side == 0 ? tree.state(child) : parent;
        if (certifier_.certify(a, b)) {
          tree.set_certified(child);
        } else {
          ++certify_refused_;
          nodes_cut_ += tree.cut(child);
          whole = false;
          break;
        }
      }
    }
    if (whole && !certifier_.certify(trees_[0].state(m.start), trees_[1].state(m.goal))) {
      ++certify_refused_;
      whole = false;
    }
    return whole;
  }

  // Appends start root -> m.start, then m.goal -> goal root; the leg's first state is the previous
  // leg's last (the shared seed) and is not repeated.
  void append_leg_path(const Meeting& m, std::vector<State>& path) {
    chain_.clear();
    for (std::size_t v = m.start; v != kNoNode; v = trees_[0].parent(v)) chain_.push_back(v);
    for (auto it = chain_.rbegin() + (path.empty() ? 0 : 1); it != chain_.rend(); ++it) path.push_back(trees_[0].state(*it));
    for (std::size_t v = m.goal; v != kNoNode; v = trees_[1].parent(v)) path.push_back(trees_[1].state(v));
  }

  // The trees of the leg that did not connect: drawn (copied into the forest) while they are small;
  // a run stopped by its time limit may hold millions of nodes, whose copy took 0.2 s past the
  // limit for 40,000 (run_limits_test), so larger ones are only counted.
  void stop_leg_trees() {
    const std::size_t shared = leg_ > 0 ? 1 : 0;  // tree 0's root is the previous leg's goal root
    if (trees_[0].size() + trees_[1].size() <= kMaxCopiedFailedTrees) {
      append_forest(nullptr);
      return;
    }
    uncopied_.nodes = trees_[0].size() + trees_[1].size() - shared;
    uncopied_.edges = trees_[0].size() + trees_[1].size() - 2;
    uncopied_.components = 2 - shared;
  }

  // Adds the current leg's trees (and their meeting edge) to the forest; tree 0's root is the
  // previous leg's goal root.
  void append_forest(const Meeting* m) {
    VertexId ids[2] = {0, 0};  // forest ids of the meeting nodes
    for (int side = 0; side < 2; ++side) {
      const Tree& tree = trees_[side];
      vertex_.resize(tree.size());
      for (std::size_t i = 0; i < tree.size(); ++i) {
        const bool shared_root = side == 0 && i == 0 && leg_ > 0;
        vertex_[i] = shared_root ? goal_root_ : forest_->add_vertex(tree.state(i));
        if (i > 0) {
          const std::size_t p = tree.parent(i);
          forest_->add_edge(vertex_[i], vertex_[p], ctx_.space.distance(tree.state(i), tree.state(p)));
        }
      }
      if (m != nullptr) ids[side] = vertex_[side == 0 ? m->start : m->goal];
      if (side == 1) goal_root_ = vertex_[0];
    }
    if (m != nullptr) {
      forest_->add_edge(ids[0], ids[1], ctx_.space.distance(forest_->state(ids[0]), forest_->state(ids[1])));
    }
  }

  const PlanningContext& ctx_;
  const core::StopCondition& stop_;
  double range_;
  bool certified_mode_;
  StraightLinePlanner local_planner_;
  EdgeCertifier certifier_;
  Tree trees_[2];
  std::shared_ptr<Roadmap> forest_;
  struct {
    std::uint64_t nodes = 0, edges = 0, components = 0;
  } uncopied_;  // the last leg's trees when too large to copy (stop_leg_trees)
  std::size_t leg_ = 0;
  VertexId goal_root_ = 0;  // forest id of the last appended leg's goal root
  core::StopReason reason_ = core::StopReason::kNone;
  State sample_, step_;
  std::vector<std::size_t> chain_;
  std::vector<VertexId> vertex_;
  std::uint64_t legs_solved_ = 0;
  std::uint64_t certify_refused_ = 0;
  std::uint64_t nodes_cut_ = 0;
};

}  // namespace

const core::SettingsSchema<RrtConnectSettings>& RrtConnectSettings::schema() {
  using S = RrtConnectSettings;
  static const core::SettingsSchema<S> schema(
      "rrt-connect", {core::real_field<S>("range", &S::range, 0, kMaxRange,
                                          "longest extension step (space metric); 0 = 0.2 x the space's maximum extent")});
  return schema;
}

double effective_range(const RrtConnectSettings& settings, const core::Space& space) {
  return settings.range > 0.0 ? settings.range : kDefaultRangeFraction * space.maximum_extent();
}

RrtConnect::RrtConnect(RrtConnectSettings settings) : settings_(settings) { settings_.validate(); }

PlanResult RrtConnect::plan(const PlanningContext& ctx, const core::StopCondition& stop, core::Rng& rng) {
  check_seeds(ctx);
  return RrtConnectRun(effective_range(settings_, ctx.space), ctx, stop).run(rng);
}

}  // namespace amp::roadmap
