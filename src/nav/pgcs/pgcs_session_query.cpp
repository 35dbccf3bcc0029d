// PgcsSession's queries (Vlassis et al., section 4): plan on the learned graph, drive the route
// (along the robot's trace when it joins the route's cells), and on a block mark the edge and plan
// again from where the robot stands.
#include <chrono>
#include <string>

#include "amp/core/error.hpp"
#include "amp/core/stop_condition.hpp"
#include "amp/nav/pgcs/pgcs_session.hpp"
#include "amp/nav/straight_leg.hpp"

namespace amp::nav {

namespace {
// Route edges a query may leave out as not known to the trace before it follows the trace wherever
// it leads instead. Each costs an A* and a flood (office map, seed 1, planning per query: at 256,
// mean 20 ms, up to 245 ms, 100 of 100 solved; at 16, mean 4 ms, 99; at 4, median 0.9 ms, 99;
// MovingAI rooms, novelty walk, seed 6: 94, 97 and 98 solved).
constexpr int kMaxLeftOut = 4;
}  // namespace

bool PgcsSession::retreat(std::size_t from, QueryRecord& rec, const core::StopCondition* stop) {
  // Back through the positions the leg passed to where it began, so that the robot replans from a
  // place its route reached and the failed attachments made there hold. A refused step of the way
  // back (sensor noise) ends the retreat where the robot stands.
  path_back_.assign(rec.trace.begin() + static_cast<std::ptrdiff_t>(from) - 1, rec.trace.end());
  const LegResult res = drive_back(simulator_, path_back_, run_.speed * task_.robot_radius, drive_rng_, stop, &rec.trace);
  rec.length += res.travelled;
  return res.end != LegEnd::kStopped;
}

QueryRecord PgcsSession::query(const Eigen::Vector2d& start, const Eigen::Vector2d& target,
                               const core::StopCondition* stop) {
  const double r = task_.robot_radius;
  auto check = [&](const Eigen::Vector2d& p, const char* what) {
    if (!simulator_.next_world().disc_free(p, r)) {
      throw ParameterError(std::string(what) + " (" + std::to_string(p.x()) + ", " + std::to_string(p.y()) +
                           "): the robot's disc is in an obstacle or outside the world");
    }
  };
  check(start, "query start");
  check(target, "query goal");
  QueryRecord rec;
  rec.start = start;
  rec.target = target;
  reachable();  // brings current_ to the world of now
  if (run_.exemplars && exemplars_step_ != pgcs_.steps()) adopt_exemplars();
  rec.shortest = current_->shortest_length(start, target);
  RobotState placed;
  placed.position = start;
  simulator_.place(placed);
  rec.trace.push_back(start);
  failed_.clear();
  blocked_now_.clear();
  bool tracing = run_.trace_legs, anywhere = false;
  const auto t_links = std::chrono::steady_clock::now();
  if (tracing) link_trace();
  rec.plan_time_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t_links).count();
  std::uint64_t portal_key = ++graph_key_;  // the portal graph's (verified and more edges: the portals)
  int left_out = 0;  // route edges left out as not known (trace_route)
  int back = -1;  // the cluster the robot last drove from
  const StraightLegSettings leg{run_.block_distance * r, 20, 3.0, run_.detour * r};
  const double speed = run_.speed * r;
  // No route the trace supports (none at all, or none found in kMaxLeftOut tries): the rest of the
  // query follows the trace wherever it leads, when it joins the robot to the target at all, and
  // otherwise goes by trial and error on the graph as it is (what was left out was only not known,
  // not seen blocked).
  const auto to_anywhere = [&] {
    tracing = false;
    anywhere = true;
    failed_.clear();
    blocked_now_.clear();
  };
  for (;;) {
    const Eigen::Vector2d from = simulator_.state().position;
    if (tracing && left_out == kMaxLeftOut) to_anywhere();
    // Waypoints: along the trace through the route's cells when it joins them; else each node,
    // preceded by its edge's portal when one is known. A node between two portals is skipped (the
    // robot cuts across its cell from portal to portal) when `shortcuts` is on; if that cut is
    // blocked, the robot goes on through the node's point instead.
    legs_.clear();
    Traced traced = Traced::kNone;
    Route route;
    if (anywhere) {  // the trace first: a route is only needed where it does not lead
      const auto t1 = std::chrono::steady_clock::now();
      traced = trace_anywhere(from, target);
      rec.plan_time_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
    }
    if (traced == Traced::kNone) {
      const auto t0 = std::chrono::steady_clock::now();
      // Tracing, an edge is verified when the trace joins its two cells side by side, and such
      // pairs are edges even when their centres are no longer Delaunay neighbours; else by the portals.
      route = planner_.plan(pgcs_, memory_, from, target, failed_, r,
                            [this, tracing](int a, int b) {
                              return tracing ? trace_linked(a, b) : portal(a, b) != nullptr;
                            },
                            [this](int k) { return node_point(k); },
                            // Tracing, the start also joins the cluster whose cell it stands in, by the
                            // trace (its nearest centres' cells may lie beyond a wall).
                            tracing && back < 0 ? traced_home(from) : back,
                            [this, tracing](int k, std::vector<int>& out) {
                              if (tracing) {
                                if (static_cast<std::size_t>(k) < trace_links_.size()) {
                                  out.insert(out.end(), trace_links_[static_cast<std::size_t>(k)].begin(),
                                             trace_links_[static_cast<std::size_t>(k)].end());
                                }
                                return;
                              }
                              if (!run_.portals) return;
                              for (int j : portals_.crossed(k)) {
                                if (portal(k, j) != nullptr) out.push_back(j);
                              }
                            },
                            &blocked_now_, tracing ? trace_key_ : portal_key);
      rec.plan_time_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (tracing && route.empty() && left_out > 0) {
        to_anywhere();
        continue;
      }
      if (route.empty()) {
        rec.unsolvable = true;
        break;
      }
      const auto t1 = std::chrono::steady_clock::now();
      if (tracing) traced = trace_route(route, from, target);
      if (tracing && traced == Traced::kNone) traced = trace_anywhere(from, target);
      rec.plan_time_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
      if (traced == Traced::kLeftOut) {
        ++left_out;
        if (stop != nullptr && stop->time_up()) break;
        continue;
      }
    }
    for (std::size_t i = 1; traced == Traced::kNone && i < route.points.size(); ++i) {
      const int u = route.nodes[i - 1], v = route.nodes[i];
      const Eigen::Vector2d* gate = u >= 0 && v >= 0 ? portal(u, v) : nullptr;
      if (gate != nullptr) {
        const bool cut = run_.shortcuts && !legs_.empty() && legs_.back().kind == Leg::kNode &&
                         legs_.back().to_node == u && legs_.size() >= 2 && legs_[legs_.size() - 2].kind == Leg::kPortal;
        if (cut) legs_.back().kind = Leg::kSkipped;
        legs_.push_back({*gate, u, v, Leg::kPortal});
      }
      legs_.push_back({route.points[i], u, v, Leg::kNode});
    }
    bool blocked = false, stopped = false;
    for (std::size_t li = 0; li < legs_.size() && !blocked && !stopped; ++li) {
      const Leg l = legs_[li];
      if (l.kind == Leg::kSkipped) continue;
      const Eigen::Vector2d leg_start = simulator_.state().position;
      const std::size_t leg_trace = rec.trace.size();
      const LegResult res = drive_straight(simulator_, l.to, speed, leg, drive_rng_, stop, &rec.trace);
      rec.length += res.travelled;
      for (std::size_t t = leg_trace; t < rec.trace.size(); ++t) trace_.visit(rec.trace[t - 1], rec.trace[t]);
      if (res.end == LegEnd::kStopped) stopped = true;
      if (res.end != LegEnd::kBlocked) continue;
      if (l.kind == Leg::kTrace) {
        // The known way is blocked here (a door closed, or the kept positions pass too near an
        // obstacle): the cells ahead are forgotten, so the next route goes round them, and a way
        // they cut is left out of later routes as not known. The edge from the robot's cluster to
        // the next one the way enters takes a strike (EdgeMemory: illegal at the `strikes`-th).
        const Eigen::Vector2d at = simulator_.state().position;
        const Eigen::Vector2d ahead = (l.to - at).norm() > 0.0 ? Eigen::Vector2d((l.to - at).normalized()) : Eigen::Vector2d::Zero();
        trace_.forget(at + ahead * (r + run_.block_distance * r), 2.0 * r);
        trace_.forget(l.to, 0.5 * trace_.geometry().cell_size());  // the leg's end: no route repeats the leg
        const int u = cell_label(trace_.geometry().cell_of(at));
        int v = -1;
        for (std::size_t k = li; k < legs_.size() && v < 0; ++k) {
          if (legs_[k].to_node != u) v = legs_[k].to_node;
        }
        if (u >= 0 && v >= 0 && node_point(u).allFinite() && node_point(v).allFinite()) {
          memory_.mark(u, v, node_point(u), node_point(v));
        }
        blocked = true;
        back = u;
        rec.blocks.push_back(at);
        if (run_.retreat && !retreat(leg_trace, rec, stop)) stopped = true;
        continue;
      }
      if (l.kind == Leg::kPortal && li > 0 && legs_[li - 1].kind == Leg::kSkipped) {
        legs_[li - 1].kind = Leg::kNode;  // the cut failed: through the node's point, then on
        li -= 2;
        continue;
      }
      const int u = l.from, v = l.to_node;
      // A node is a cluster, not a point: stopped within min(sigma, r) of its point, the robot is
      // in it (a point beside a wall or a door frame is often unreachable exactly).
      if (l.kind == Leg::kNode && v >= 0 &&
          (simulator_.state().position - l.to).squaredNorm() <= std::min(pgcs_.variance(v), r * r)) {
        continue;
      }
      blocked = true;
      back = u >= 0 ? u : -1;
      if (u >= 0 && v >= 0) {
        // An edge the explorer crossed joins free cells: a block on it says the way through its
        // portal is undrivable (a door frame clipped), not that the edge is illegal. It loses its
        // portal and is left out of this query; as a plain edge it may be tried again later.
        if (portal(u, v) != nullptr) {
          portals_.drop(u, v);
          portal_key = ++graph_key_;
          blocked_now_.mark(u, v, node_point(u), node_point(v));
        } else {
          memory_.mark(u, v, node_point(u), node_point(v));
        }
      } else if (v == Route::kTarget) {
        failed_.push_back({u >= 0 ? target : leg_start, u >= 0 ? u : Route::kTarget});
      } else {
        failed_.push_back({leg_start, v});
      }
      rec.blocks.push_back(simulator_.state().position);
      if (run_.retreat && !retreat(leg_trace, rec, stop)) stopped = true;
    }
    if (stopped) break;
    if (!blocked) {
      rec.solved = true;
      break;
    }
    if (rec.replans == run_.max_replans) break;  // given up: this block is not replanned
    ++rec.replans;
  }
  if (rec.solved && std::isfinite(rec.shortest) && rec.shortest > 0.0) rec.ratio = rec.length / rec.shortest;
  if (rec.solved && rec.shortest == 0.0) rec.ratio = 1.0;
  rec.illegal_edges = memory_.size();
  rec.left_out = left_out;
  return rec;
}

}  // namespace amp::nav
