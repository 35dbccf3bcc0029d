#include "amp/nav/pgcs/pgcs_explorer.hpp"

#include <algorithm>
#include <cmath>

#include "amp/nav/pgcs/trace_corridor.hpp"
#include "amp/nav/simulator.hpp"

namespace amp::nav {

namespace {

// At most this many exploration positions are kept for drawing.
constexpr long kTracePoints = 4000;

RandomWalkSettings walk_settings(const NavTask& task, const PgcsRunSettings& run) {
  const double r = task.robot_radius;
  // The novelty walk looks as far as a few steps of its own persistence (turn_every steps).
  const double lookahead = run.exploration == "novelty" ? std::min(run.turn_every * run.speed, 20.0) * r : 0.0;
  return {run.speed * r, run.turn_every, run.avoid_distance * r, lookahead};
}

}  // namespace

PgcsExplorer::PgcsExplorer(const NavTask& task, const PgcsRunSettings& run, learn::PgcsSettings pgcs, core::Rng rng)
    : portals_on_(run.portals),
      exemplars_on_(run.exemplars),
      keep_every_(std::max(1L, run.steps / kTracePoints)),
      pgcs_(pgcs),
      portals_(pgcs.window),
      walk_(walk_settings(task, run),
            [this](const Eigen::Vector2d& p) {
              // How visited p is: minus its distance to the nearest centre. (The mixture density
              // would underflow to 0 a few sigma out, leaving every unexplored direction tied.)
              const int k = pgcs_.triangulation().nearest(p);
              return k < 0 ? 0.0 : -(p - pgcs_.mean(k)).norm();
            }),
      rng_(rng) {}

void PgcsExplorer::step(Simulator& simulator, TraceCorridor& corridor) {
  const Eigen::Vector2d command = walk_.command(simulator, last_blocked_, rng_);
  const Eigen::Vector2d before = simulator.state().position;
  last_blocked_ = simulator.step(command, rng_).blocked;
  const Eigen::Vector2d& x = simulator.state().position;
  pgcs_.step(x);
  corridor.visit(before, x);
  ++steps_;
  ++revision_;
  track_clusters(x);
  if (steps_ % keep_every_ == 0) positions_.push_back(x);
}

void PgcsExplorer::track_clusters(const Eigen::Vector2d& x) {
  const long n = pgcs_.steps();
  const learn::PgcsSettings& ps = pgcs_.settings();
  if (n == 1 || n % ps.insert_every == 0 || n % ps.delete_every == 0) note_births();
  // The Voronoi cell the robot stands in (its nearest centre), not the PGCS winner: the planning
  // graph is the Delaunay graph, the dual of these cells, so a move from one cell into another is
  // the evidence for that very edge (the winner, whose criterion weighs sigma and pi, may be a
  // wide cluster far off, and its "crossings" would join clusters that are not neighbours).
  const int w = pgcs_.triangulation().nearest(x);
  if (w >= 0) note_exemplar(w, x);
  if (portals_on_ && w >= 0 && last_winner_ >= 0 && w != last_winner_ && alive_[static_cast<std::size_t>(last_winner_)]) {
    portals_.observe(last_winner_, born_[static_cast<std::size_t>(last_winner_)], w, born_[static_cast<std::size_t>(w)],
                     0.5 * (x + last_position_));
  }
  last_winner_ = w;
  last_position_ = x;
}

void PgcsExplorer::note_births() {
  std::fill(alive_.begin(), alive_.end(), 0);
  for (int k : pgcs_.ids()) {
    const auto id = static_cast<std::size_t>(k);
    if (id >= born_.size()) {
      born_.resize(id + 1, -1), alive_.resize(id + 1, 0);
      exemplar_.resize(id + 1, Eigen::Vector2d::Zero()), exemplar_born_.resize(id + 1, -1);
    }
    if (born_[id] < 0 || (!was_alive_.empty() && (id >= was_alive_.size() || !was_alive_[id]))) {
      if (born_[id] >= 0) portals_.forget(k);  // the id is reused: its old pairs are not this cluster's
      born_[id] = pgcs_.steps();
    }
    alive_[id] = 1;
  }
  for (std::size_t id = 0; id < was_alive_.size(); ++id) {
    if (was_alive_[id] != 0 && alive_[id] == 0) portals_.forget(static_cast<int>(id));  // deleted
  }
  was_alive_ = alive_;
}

void PgcsExplorer::note_exemplar(int k, const Eigen::Vector2d& p) {
  const auto u = static_cast<std::size_t>(k);
  if (u >= born_.size()) return;
  if (exemplar_born_[u] != born_[u] || (p - pgcs_.mean(k)).squaredNorm() < (exemplar_[u] - pgcs_.mean(k)).squaredNorm()) {
    exemplar_[u] = p;
    exemplar_born_[u] = born_[u];
  }
}

void PgcsExplorer::adopt_exemplars() {
  if (!exemplars_on_ || exemplars_step_ == pgcs_.steps()) return;
  // A cluster born late may never have had the robot in its cell since, though the robot stood there
  // before (under other clusters): such cells would drop out of every route, and with them whole
  // rooms on a large map (12% of 1,000 clusters on the MovingAI rooms map). The kept exploration
  // positions (an even subsample of every position) give them an exemplar where they can.
  for (const Eigen::Vector2d& p : positions_) {
    const int k = pgcs_.triangulation().nearest(p);
    if (k >= 0) note_exemplar(k, p);
  }
  exemplars_step_ = pgcs_.steps();
  ++revision_;
}

void PgcsExplorer::drop_portal(int a, int b) {
  portals_.drop(a, b);
  ++revision_;
}

const Eigen::Vector2d* PgcsExplorer::portal(int a, int b) const {
  if (!portals_on_) return nullptr;
  const auto ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(b);
  if (ua >= born_.size() || ub >= born_.size()) return nullptr;
  return portals_.find(a, born_[ua], b, born_[ub]);
}

Eigen::Vector2d PgcsExplorer::node_point(int k) const {
  const auto u = static_cast<std::size_t>(k);
  if (!exemplars_on_) return pgcs_.mean(k);
  // A cluster whose cell the robot has not entered since it was made has no exemplar: nothing says
  // the robot can stand in it, so routes leave it out.
  if (u >= born_.size() || exemplar_born_[u] != born_[u]) return Eigen::Vector2d::Constant(std::nan(""));
  return exemplar_[u];
}

}  // namespace amp::nav
