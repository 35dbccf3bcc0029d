// PgcsSession's queries (Vlassis et al., section 4): plan on the learned graph, drive the route
// (along the robot's trace when it joins the route's cells), and on a block mark the edge and plan
// again from where the robot stands.
#include "amp/nav/pgcs/pgcs_query_driver.hpp"

#include <chrono>
#include <cmath>
#include <string>

#include "amp/core/error.hpp"
#include "amp/core/stop_condition.hpp"
#include "amp/nav/free_mask.hpp"
#include "amp/nav/pgcs/pgcs_explorer.hpp"
#include "amp/nav/pgcs/reference_worlds.hpp"
#include "amp/nav/pgcs/trace_corridor.hpp"
#include "amp/nav/simulator.hpp"

namespace amp::nav {

namespace {
// Route edges a query may leave out as not known to the trace before it follows the trace wherever
// it leads instead. Each costs an A* and a flood (office map, seed 1, planning per query: at 256,
// mean 20 ms, up to 245 ms, 100 of 100 solved; at 16, mean 4 ms, 99; at 4, median 0.9 ms, 99;
// MovingAI rooms, novelty walk, seed 6: 94, 97 and 98 solved).
constexpr int kMaxLeftOut = 4;

// Runs f, adding its wall time to the query's planning time.
template <class F>
auto timed(QueryRecord& rec, F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  auto result = f();
  rec.plan_time_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}
}  // namespace

PgcsQueryDriver::PgcsQueryDriver(const PgcsRunSettings& run, double radius, core::Rng rng, Simulator& simulator,
                                 TraceCorridor& corridor, ReferenceWorlds& worlds, PgcsExplorer& explorer,
                                 PgcsRouter& router)
    : run_(run),
      radius_(radius),
      rng_(rng),
      simulator_(simulator),
      corridor_(corridor),
      worlds_(worlds),
      explorer_(explorer),
      router_(router),
      leg_{run.block_distance * radius, 20, 3.0, run.detour * radius} {}

QueryRecord PgcsQueryDriver::query(const Eigen::Vector2d& start, const Eigen::Vector2d& target,
                                   const core::StopCondition* stop) {
  QueryRecord rec = begin(start, target);
  Progress q;
  q.target = target;
  q.tracing = run_.trace_legs;
  timed(rec, [&] {
    if (q.tracing) router_.link_trace();
    return 0;
  });
  for (;;) {
    if (q.tracing && q.left_out == kMaxLeftOut) to_anywhere(q);
    const Planned planned = plan_legs(q, rec, stop);
    if (planned == Planned::kAgain) continue;
    if (planned == Planned::kNoRoute) rec.unsolvable = true;
    if (planned != Planned::kLegs) break;
    const Driven driven = drive_legs(q, rec, stop);
    if (driven == Driven::kStopped) break;
    if (driven == Driven::kArrived) {
      rec.solved = true;
      break;
    }
    if (rec.replans == run_.max_replans) break;  // given up: this block is not replanned
    ++rec.replans;
  }
  end(rec, q);
  return rec;
}

QueryRecord PgcsQueryDriver::begin(const Eigen::Vector2d& start, const Eigen::Vector2d& target) {
  const auto check = [&](const Eigen::Vector2d& p, const char* what) {
    if (!simulator_.next_world().disc_free(p, radius_)) {
      throw ParameterError(std::string(what) + " (" + std::to_string(p.x()) + ", " + std::to_string(p.y()) +
                           "): the robot's disc is in an obstacle or outside the world");
    }
  };
  check(start, "query start");
  check(target, "query goal");
  QueryRecord rec;
  rec.start = start;
  rec.target = target;
  worlds_.reachable_at(simulator_.step_count());  // the grid of the world of now
  rec.shortest = worlds_.now().shortest_length(start, target);
  RobotState placed;
  placed.position = start;
  simulator_.place(placed);
  rec.trace.push_back(start);
  router_.begin_query();
  return rec;
}

void PgcsQueryDriver::end(QueryRecord& rec, const Progress& q) const {
  if (rec.solved && std::isfinite(rec.shortest) && rec.shortest > 0.0) rec.ratio = rec.length / rec.shortest;
  if (rec.solved && rec.shortest == 0.0) rec.ratio = 1.0;
  rec.illegal_edges = router_.memory().size();
  rec.left_out = q.left_out;
}

// No route the trace supports (none at all, or none found in kMaxLeftOut tries): the rest of the
// query follows the trace wherever it leads, when it joins the robot to the target at all, and
// otherwise goes by trial and error on the graph as it is (what was left out was only not known,
// not seen blocked).
void PgcsQueryDriver::to_anywhere(Progress& q) {
  q.tracing = false;
  q.anywhere = true;
  router_.clear_failures();
}

PgcsQueryDriver::Planned PgcsQueryDriver::plan_legs(Progress& q, QueryRecord& rec, const core::StopCondition* stop) {
  using Traced = PgcsRouter::Traced;
  const Eigen::Vector2d from = simulator_.state().position;
  legs_.clear();
  // Waypoints: along the trace through the route's cells when it joins them; else each node,
  // preceded by its edge's portal when one is known (legs_along).
  Traced traced = Traced::kNone;
  if (q.anywhere) traced = timed(rec, [&] { return router_.trace_anywhere(from, q.target, way_); });
  if (traced == Traced::kNone) {
    // Tracing, an edge is verified when the trace joins its two cells side by side (TraceGraph);
    // else by the portals (PortalGraph).
    const Route route = timed(rec, [&] { return router_.plan(from, q.target, q.tracing, q.back); });
    if (q.tracing && route.empty() && q.left_out > 0) {
      to_anywhere(q);
      return Planned::kAgain;
    }
    if (route.empty()) return Planned::kNoRoute;
    traced = timed(rec, [&] {
      Traced t = q.tracing ? router_.trace_route(route, from, q.target, way_) : Traced::kNone;
      if (q.tracing && t == Traced::kNone) t = router_.trace_anywhere(from, q.target, way_);
      return t;
    });
    if (traced == Traced::kLeftOut) {
      ++q.left_out;
      return stop != nullptr && stop->time_up() ? Planned::kStopped : Planned::kAgain;
    }
    if (traced == Traced::kNone) legs_along(route);
  }
  if (traced == Traced::kDriven) legs_along_trace();
  return Planned::kLegs;
}

// A node between two portals is skipped (the robot cuts across its cell from portal to portal) when
// `shortcuts` is on; if that cut is blocked, the robot goes on through the node's point instead.
void PgcsQueryDriver::legs_along(const Route& route) {
  for (std::size_t i = 1; i < route.points.size(); ++i) {
    const int u = route.nodes[i - 1], v = route.nodes[i];
    const Eigen::Vector2d* gate = u >= 0 && v >= 0 ? explorer_.portal(u, v) : nullptr;
    if (gate != nullptr) {
      const bool cut = run_.shortcuts && !legs_.empty() && legs_.back().kind == Leg::kNode &&
                       legs_.back().to_node == u && legs_.size() >= 2 && legs_[legs_.size() - 2].kind == Leg::kPortal;
      if (cut) legs_.back().kind = Leg::kSkipped;
      legs_.push_back({*gate, u, v, Leg::kPortal});
    }
    legs_.push_back({route.points[i], u, v, Leg::kNode});
  }
}

void PgcsQueryDriver::legs_along_trace() {
  for (std::size_t i = 1; i < way_.size(); ++i) {
    legs_.push_back({way_[i], router_.label_at(way_[i - 1]), router_.label_at(way_[i]), Leg::kTrace});
  }
}

PgcsQueryDriver::Driven PgcsQueryDriver::drive_legs(Progress& q, QueryRecord& rec, const core::StopCondition* stop) {
  bool blocked = false, stopped = false;
  for (std::size_t li = 0; li < legs_.size() && !blocked && !stopped; ++li) {
    const Leg l = legs_[li];
    if (l.kind == Leg::kSkipped) continue;
    const Eigen::Vector2d leg_start = simulator_.state().position;
    const std::size_t leg_trace = rec.trace.size();
    const LegResult res = drive_leg(l.to, rec, stop);
    if (res.end == LegEnd::kStopped) stopped = true;
    if (res.end != LegEnd::kBlocked) continue;
    if (l.kind == Leg::kPortal && li > 0 && legs_[li - 1].kind == Leg::kSkipped) {
      legs_[li - 1].kind = Leg::kNode;  // the cut failed: through the node's point, then on
      li -= 2;
      continue;
    }
    // A node is a cluster, not a point: stopped within min(sigma, r) of its point, the robot is in
    // it (a point beside a wall or a door frame is often unreachable exactly).
    if (l.kind == Leg::kNode && l.to_node >= 0 &&
        (simulator_.state().position - l.to).squaredNorm() <= std::min(explorer_.clusters().variance(l.to_node), radius_ * radius_)) {
      continue;
    }
    blocked = true;
    if (l.kind == Leg::kTrace) {
      trace_leg_blocked(li, q, rec);
    } else {
      leg_blocked(l, leg_start, q, rec);
    }
    if (run_.retreat && !retreat(leg_trace, rec, stop)) stopped = true;
  }
  return stopped ? Driven::kStopped : blocked ? Driven::kBlocked : Driven::kArrived;
}

LegResult PgcsQueryDriver::drive_leg(const Eigen::Vector2d& to, QueryRecord& rec, const core::StopCondition* stop) {
  const std::size_t leg_trace = rec.trace.size();
  const LegResult res = drive_straight(simulator_, to, run_.speed * radius_, leg_, rng_, stop, &rec.trace);
  rec.length += res.travelled;
  for (std::size_t t = leg_trace; t < rec.trace.size(); ++t) corridor_.visit(rec.trace[t - 1], rec.trace[t]);
  return res;
}

void PgcsQueryDriver::trace_leg_blocked(std::size_t li, Progress& q, QueryRecord& rec) {
  // The known way is blocked here (a door closed, or the kept positions pass too near an obstacle):
  // the cells ahead are forgotten, so the next route goes round them, and a way they cut is left
  // out of later routes as not known. The edge from the robot's cluster to the next one the way
  // enters takes a strike (EdgeMemory: illegal at the `strikes`-th).
  const Leg& l = legs_[li];
  const double r = radius_;
  const Eigen::Vector2d at = simulator_.state().position;
  const Eigen::Vector2d ahead = (l.to - at).norm() > 0.0 ? Eigen::Vector2d((l.to - at).normalized()) : Eigen::Vector2d::Zero();
  corridor_.forget(at + ahead * (r + run_.block_distance * r), 2.0 * r);
  corridor_.forget(l.to, 0.5 * corridor_.geometry().cell_size());  // the leg's end: no route repeats the leg
  const int u = router_.label_at(at);
  int v = -1;
  for (std::size_t k = li; k < legs_.size() && v < 0; ++k) {
    if (legs_[k].to_node != u) v = legs_[k].to_node;
  }
  if (u >= 0 && v >= 0 && explorer_.node_point(u).allFinite() && explorer_.node_point(v).allFinite()) router_.strike(u, v);
  q.back = u;
  rec.blocks.push_back(at);
}

void PgcsQueryDriver::leg_blocked(const Leg& l, const Eigen::Vector2d& leg_start, Progress& q, QueryRecord& rec) {
  const int u = l.from, v = l.to_node;
  q.back = u >= 0 ? u : -1;
  if (u >= 0 && v >= 0) {
    // An edge the explorer crossed joins free cells: a block on it says the way through its portal
    // is undrivable (a door frame clipped), not that the edge is illegal. It loses its portal and is
    // left out of this query; as a plain edge it may be tried again later.
    if (explorer_.portal(u, v) != nullptr) {
      router_.drop_portal(u, v);
    } else {
      router_.strike(u, v);
    }
  } else {
    router_.fail_end(u, v, leg_start, rec.target);
  }
  rec.blocks.push_back(simulator_.state().position);
}

bool PgcsQueryDriver::retreat(std::size_t from, QueryRecord& rec, const core::StopCondition* stop) {
  // Back through the positions the leg passed to where it began, so that the robot replans from a
  // place its route reached and the failed attachments made there hold. A refused step of the way
  // back (sensor noise) ends the retreat where the robot stands.
  path_back_.assign(rec.trace.begin() + static_cast<std::ptrdiff_t>(from) - 1, rec.trace.end());
  const LegResult res = drive_back(simulator_, path_back_, run_.speed * radius_, rng_, stop, &rec.trace);
  rec.length += res.travelled;
  return res.end != LegEnd::kStopped;
}

}  // namespace amp::nav
