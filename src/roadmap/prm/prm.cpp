#include "amp/roadmap/prm/prm.hpp"

#include <algorithm>
#include <string>

#include "amp/core/error.hpp"
#include "amp/roadmap/prm/lifelong_astar.hpp"
#include "amp/roadmap/local_planners/edge_certifier.hpp"
#include "amp/roadmap/neighbors/kd_tree_neighbors.hpp"
#include "amp/roadmap/prm/k_nearest_connection.hpp"
#include "amp/roadmap/prm/path_smoothing.hpp"
#include "amp/roadmap/local_planners/straight_line_planner.hpp"
#include "amp/roadmap/samplers/uniform_sampler.hpp"

namespace amp::roadmap {

namespace {

// Upper bound on the up-front reservation: a node limit of 10^9 must not reserve 10^9 states.
constexpr std::size_t kMaxReservedNodes = 200000;

// One PRM run: the roadmap and the parts that grow it.
class PrmRun {
 public:
  PrmRun(const PrmSettings& settings, const PrmParts& parts, const PlanningContext& ctx,
         const core::StopCondition& stop)
      : settings_(settings),
        ctx_(ctx),
        stop_(stop),
        roadmap_(std::make_shared<Roadmap>()),
        certifier_(ctx.space, ctx.checker, &stop) {
    if (parts.observed_sampler) {
      ObservedSampler made = parts.observed_sampler(ctx);
      sampler_ = std::move(made.sampler);
      observer_ = std::move(made.observer);
    } else {
      sampler_ = parts.sampler ? parts.sampler(ctx) : std::make_unique<UniformSampler>(ctx.space, ctx.checker);
      if (parts.observer) observer_ = parts.observer(ctx);
    }
    local_planner_ = parts.local_planner ? parts.local_planner(ctx)
                                         : std::make_unique<StraightLinePlanner>(ctx.space, ctx.checker, &stop);
    if (parts.connection) {
      connection_ = parts.connection(ctx);
    } else {
      auto nn = std::make_unique<KdTreeNeighbors>(ctx.space, &ctx.checker.counters());
      nn->reserve(std::min(stop.node_limit(), kMaxReservedNodes));
      connection_ = std::make_unique<KNearestConnection>(std::move(nn), static_cast<std::size_t>(settings.k));
    }
    const std::size_t k = static_cast<std::size_t>(settings.k);
    if (parts.initial) {
      *roadmap_ = *parts.initial;
      for (VertexId v = 0; v < roadmap_->vertex_count(); ++v) connection_->add(v, roadmap_->state(v));
    }
    roadmap_->reserve(std::min(stop.node_limit(), kMaxReservedNodes), 2 * k);
    neighbors_.reserve(k);
  }

  PlanResult run(core::Rng& rng) {
    State q;
    PlanResult result;
    // The query's seeds count against the node limit like any vertex: a roadmap that cannot take
    // them (a reused training roadmap already at the limit, a limit below the seed count) stops here.
    const bool room = roadmap_->vertex_count() + ctx_.seeds.size() <= stop_.node_limit();
    if (room) {
      for (const State& s : ctx_.seeds) seed_ids_.push_back(insert(s, true));
    } else {
      result.status = status_for(core::StopReason::kNodeLimit);
    }
    while (room) {
      if (seeds_may_connect() && find_path(result.path)) {
        result.status = core::PlanStatus::kSolved;
        break;
      }
      const core::StopReason reason = stop_.check(roadmap_->vertex_count());
      if (reason != core::StopReason::kNone) {
        result.status = status_for(reason);
        break;
      }
      if (sampler_->sample(rng, q)) {
        insert(q, false);
      } else {
        ++failed_samples_;
      }
    }
    if (result.status == core::PlanStatus::kSolved && settings_.smooth) smooth(rng, result.path);
    result.nodes = roadmap_->vertex_count();
    result.edges = roadmap_->edge_count();
    result.components = roadmap_->component_count();
    result.extra["failed_samples"] = static_cast<double>(failed_samples_);
    if (settings_.lazy) {
      result.extra["lazy_edges_removed"] = static_cast<double>(removed_edges_ - refused_edges_);
      result.extra["lazy_path_searches"] = static_cast<double>(path_searches_);
      result.extra["lazy_paths_rejected"] = static_cast<double>(rejected_paths_);
    }
    result.extra["certify_refused_edges"] = static_cast<double>(refused_edges_);
    certifier_.report(result.extra);
    if (settings_.smooth) result.extra["shortcuts"] = static_cast<double>(shortcuts_);
    if (observer_) observer_->report(result.extra);
    local_planner_->report(result.extra);
    result.roadmap = roadmap_;
    return result;
  }

 private:
  // Adds q and tries its connection candidates (lazy: adds them unchecked). With an observer, also
  // counts the distinct components q joins: an edge to a vertex not yet in q's component joins one
  // more (union-find queries only: the run's CD calls and results are unchanged).
  VertexId insert(const State& q, bool seed) {
    const VertexId v = roadmap_->add_vertex(q);
    connection_->candidates(*roadmap_, v, neighbors_);
    Insertion info{v, seed, 0, 0, 0};
    for (const Neighbor& n : neighbors_) {
      if (settings_.skip_same_component && roadmap_->same_component(v, n.index)) continue;
      ++info.attempts;
      const bool joins = observer_ && !roadmap_->same_component(v, n.index);
      if (settings_.lazy) {
        add_edge(v, n.index, n.distance, EdgeCheck::kUnchecked);
      } else if (local_planner_->connect_edge(q, roadmap_->state(n.index),
                                              EdgeRequest{v, n.index, roadmap_->vertex_count()}) &&
                 (!certify_all() || certify_edge(v, n.index))) {
        add_edge(v, n.index, n.distance, certify_all() ? EdgeCheck::kCertified : EdgeCheck::kValid);
      } else {
        continue;
      }
      ++info.successes;
      if (joins) ++info.components_joined;
    }
    connection_->add(v, q);
    if (observer_) observer_->inserted(*roadmap_, info);
    return v;
  }

  // The union-find's answer while it is current. Once edges have been removed (Lazy PRM's failed
  // edges, refused certificates) rebuilding it would cost O(V + E) after every removal, so the
  // repaired search decides instead: it costs little when little changed.
  bool seeds_may_connect() const { return roadmap_->components_stale() || seeds_connected(); }

  bool seeds_connected() const {
    for (std::size_t i = 1; i < seed_ids_.size(); ++i) {
      if (!roadmap_->same_component(seed_ids_[0], seed_ids_[i])) return false;
    }
    return true;
  }

  // Every roadmap change goes through these two, so that each leg's search can repair itself.
  void add_edge(VertexId a, VertexId b, double cost, EdgeCheck check) {
    roadmap_->add_edge(a, b, cost, check);
    for (LifelongAStar& leg : legs_) {
      leg.touch(a);
      leg.touch(b);
    }
  }
  void remove_edge(VertexId a, VertexId b) {
    roadmap_->remove_edge(a, b);
    ++removed_edges_;
    for (LifelongAStar& leg : legs_) {
      leg.touch(a);
      leg.touch(b);
    }
  }

  // Vertex path seed 0 -> seed 1 -> ...; segment_starts_ marks where each seed's leg begins. Each
  // leg keeps its search between calls and repairs it (LifelongAStar).
  bool search_all(std::vector<VertexId>& ids) {
    if (legs_.empty()) {
      for (std::size_t i = 1; i < seed_ids_.size(); ++i) legs_.emplace_back(seed_ids_[i - 1], seed_ids_[i]);
    }
    ++path_searches_;
    ids.assign(1, seed_ids_[0]);
    segment_starts_.assign(1, 0);
    for (std::size_t i = 1; i < seed_ids_.size(); ++i) {
      if (!legs_[i - 1].search(*roadmap_, ctx_.space, leg_)) return false;
      ids.insert(ids.end(), leg_.begin() + 1, leg_.end());
      segment_starts_.push_back(ids.size() - 1);
    }
    return true;
  }

  bool certify_all() const { return ctx_.edge_check == core::EdgeCheckMode::kCertified; }

  // Certifies the edge's whole motion: the local planner's waypoints between the two vertices and
  // the straight segments that join them. Certification is query work when it runs on a path.
  bool certify_edge(VertexId a, VertexId b) {
    edge_states_.clear();
    append_waypoints(a, b, edge_states_);
    const State* from = &roadmap_->state(a);
    for (const State& w : edge_states_) {
      if (!certifier_.certify(*from, w)) return false;
      from = &w;
    }
    return certifier_.certify(*from, roadmap_->state(b));
  }

  // A shortest path through the seeds, whose edges are then checked in two passes, each over the
  // whole path: first every unchecked edge at the space's resolution (Lazy PRM's check), then, once
  // none failed, every edge not yet certified. Every edge that fails a pass is removed, so one
  // search's path costs one repair however many of its edges fail, and the search is repaired, not
  // redone. False when the seeds fall apart.
  bool find_path(std::vector<State>& path) {
    std::vector<VertexId> ids;
    for (;;) {
      if (!search_all(ids)) return false;
      if (check_unchecked_edges(ids) && certify_edges(ids)) break;
      ++rejected_paths_;
      if (stop_.should_stop(roadmap_->vertex_count())) return false;  // the main loop reports why
    }
    path.clear();
    std::size_t next_seed = 0;
    for (std::size_t i = 0; i < ids.size(); ++i) {
      if (i > 0) append_waypoints(ids[i - 1], ids[i], path);
      // segment_starts_ now counts in path states, waypoints included.
      if (next_seed < segment_starts_.size() && segment_starts_[next_seed] == i) segment_starts_[next_seed++] = path.size();
      path.push_back(roadmap_->state(ids[i]));
    }
    return true;
  }

  // Lazy PRM's check of the path's unchecked edges; true when none failed. Each one checked is kept
  // as valid or removed.
  bool check_unchecked_edges(const std::vector<VertexId>& ids) {
    bool all_valid = true;
    for (std::size_t i = 1; i < ids.size(); ++i) {
      const VertexId a = ids[i - 1], b = ids[i];
      if (roadmap_->edge_check(a, b) != EdgeCheck::kUnchecked) continue;
      if (local_planner_->connect(roadmap_->state(a), roadmap_->state(b))) {
        roadmap_->mark(a, b, EdgeCheck::kValid);
      } else {
        remove_edge(a, b);
        all_valid = false;
      }
    }
    return all_valid;
  }

  // Certifies every edge of the path not yet certified; true when all were. Each one is kept as
  // certified or removed.
  bool certify_edges(const std::vector<VertexId>& ids) {
    bool all_certified = true;
    for (std::size_t i = 1; i < ids.size(); ++i) {
      const VertexId a = ids[i - 1], b = ids[i];
      if (roadmap_->edge_check(a, b) == EdgeCheck::kCertified) continue;
      bool certified = false;
      {
        const core::PhaseScope query(ctx_.checker.counters(), core::Phase::kQuery);
        certified = certify_edge(a, b);
      }
      if (certified) {
        roadmap_->mark(a, b, EdgeCheck::kCertified);
      } else {
        ++refused_edges_;
        remove_edge(a, b);
        all_certified = false;
      }
    }
    return all_certified;
  }

  // The local planner's states between a and b (none for straight edges). Each edge was made by
  // connect_edge(newer vertex, older vertex), so it is asked in that direction; any CD calls this
  // takes are query work.
  void append_waypoints(VertexId a, VertexId b, std::vector<State>& path) {
    const core::PhaseScope query(ctx_.checker.counters(), core::Phase::kQuery);
    const VertexId newer = std::max(a, b), older = std::min(a, b);
    local_planner_->edge_waypoints(roadmap_->state(newer), roadmap_->state(older),
                                   EdgeRequest{newer, older, roadmap_->vertex_count()}, waypoints_);
    if (newer == a) {
      path.insert(path.end(), waypoints_.begin(), waypoints_.end());
    } else {
      path.insert(path.end(), waypoints_.rbegin(), waypoints_.rend());
    }
  }

  // Shortcuts each seed-to-seed leg separately so that the path still passes through every seed.
  void smooth(core::Rng& rng, std::vector<State>& path) {
    // Back to kPlanning afterwards, or kTraining inside a learner.
    const core::PhaseScope query(ctx_.checker.counters(), core::Phase::kQuery);
    std::vector<State> out, leg;
    for (std::size_t s = 1; s < segment_starts_.size(); ++s) {
      leg.assign(path.begin() + static_cast<std::ptrdiff_t>(segment_starts_[s - 1]),
                 path.begin() + static_cast<std::ptrdiff_t>(segment_starts_[s]) + 1);
      CertifiedLocalPlanner shortcut(*local_planner_, certifier_);  // a shortcut is certified too
      shortcuts_ += shortcut_path(shortcut, rng, settings_.smooth_attempts, leg, &stop_);
      out.insert(out.end(), leg.begin() + (out.empty() ? 0 : 1), leg.end());
    }
    if (segment_starts_.size() < 2) out = path;  // a single seed: nothing to smooth
    path = std::move(out);
  }

  const PrmSettings& settings_;
  const PlanningContext& ctx_;
  const core::StopCondition& stop_;
  std::shared_ptr<Roadmap> roadmap_;
  std::unique_ptr<Sampler> sampler_;
  std::unique_ptr<LocalPlanner> local_planner_;
  std::unique_ptr<ConnectionStrategy> connection_;
  std::unique_ptr<InsertionObserver> observer_;
  EdgeCertifier certifier_;
  std::vector<LifelongAStar> legs_;  // one search per seed-to-seed leg
  std::vector<Neighbor> neighbors_;
  std::vector<VertexId> seed_ids_;
  std::vector<VertexId> leg_;
  std::vector<State> waypoints_;
  std::vector<State> edge_states_;
  std::vector<std::size_t> segment_starts_;
  std::uint64_t failed_samples_ = 0;
  std::uint64_t removed_edges_ = 0;
  std::uint64_t refused_edges_ = 0;  // removed because certification failed
  std::uint64_t path_searches_ = 0;  // searches for a candidate path (each a repair after the first)
  std::uint64_t rejected_paths_ = 0;  // candidate paths found with an edge that failed
  int shortcuts_ = 0;
};

}  // namespace

const core::SettingsSchema<PrmSettings>& PrmSettings::schema() {
  using S = PrmSettings;
  static const core::SettingsSchema<S> schema(
      "prm", {core::integer_field<S>("k", &S::k, 1, kMaxNeighbours, "neighbours tried per new node"),
              core::bool_field<S>("lazy", &S::lazy, "check edges only when on a candidate path"),
              core::bool_field<S>("smooth", &S::smooth, "shortcut the solution path"),
              core::integer_field<S>("smooth_attempts", &S::smooth_attempts, 0, 1e6, "shortcut attempts per leg"),
              core::bool_field<S>("skip_same_component", &S::skip_same_component,
                                  "do not try neighbours already in the new node's component")});
  return schema;
}

Prm::Prm(PrmSettings settings, PrmParts parts) : settings_(settings), parts_(std::move(parts)) {
  settings_.validate();
}

PlanResult Prm::plan(const PlanningContext& ctx, const core::StopCondition& stop, core::Rng& rng) {
  check_seeds(ctx);
  return PrmRun(settings_, parts_, ctx, stop).run(rng);
}

}  // namespace amp::roadmap
