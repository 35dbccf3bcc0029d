#include "amp/nav/pgcs/pgcs_session.hpp"

#include <algorithm>
#include <cmath>

#include "amp/core/error.hpp"
#include "amp/core/stop_condition.hpp"
#include "amp/nav/free_mask.hpp"
#include "amp/nav/holonomic_disc.hpp"

namespace amp::nav {

namespace {

// Seed streams of a session: exploration, query pairs, driving (sensor noise while driving).
enum Stream : std::uint64_t { kExplore = 0, kQueries = 1, kDrive = 2 };
// At most this many exploration positions are kept for drawing.
constexpr long kTracePoints = 4000;

Simulator make_simulator(const NavTask& task, const PgcsRunSettings& run) {
  const double r = task.robot_radius;
  SimulatorSettings s;
  s.contact_tolerance = std::min(1e-6, 1e-3 * r);
  s.sensors.max_range = run.sensor_range * r;
  s.sensors.noise_stddev = run.sensor_noise * r;
  const auto robot = std::make_shared<const HolonomicDisc>(HolonomicDiscSettings{r, run.speed * r / s.time_step});
  RobotState start;
  start.position = task.start;
  return Simulator(task.timeline, robot, start, s);
}

// The trace's raster: cells of the robot's radius over the reference grid's extent (coarser when
// that would pass kMaxTraceCells). Finer cells make the trace a web of thin lines rather than an
// area: office map and MovingAI rooms (novelty), seed 1, half a radius: paths 1.10x and 1.10x the
// grid-shortest, 100 and 96 of 100 queries solved; a radius: 1.06x and 1.11x, 100 and 98.
constexpr double kMaxTraceCells = 4e6;
FreeMask trace_raster(const FreeMask& reference, double radius) {
  const double w = reference.width() * reference.cell_size(), h = reference.height() * reference.cell_size();
  const double cell = std::max(radius, std::sqrt(w * h / kMaxTraceCells));
  return FreeMask(std::max(1, static_cast<int>(std::ceil(w / cell))), std::max(1, static_cast<int>(std::ceil(h / cell))),
                  cell, reference.origin());
}

RandomWalkSettings walk_settings(const NavTask& task, const PgcsRunSettings& run) {
  const double r = task.robot_radius;
  // The novelty walk looks as far as a few steps of its own persistence (turn_every steps).
  const double lookahead = run.exploration == "novelty" ? std::min(run.turn_every * run.speed, 20.0) * r : 0.0;
  return {run.speed * r, run.turn_every, run.avoid_distance * r, lookahead};
}

}  // namespace

const core::SettingsSchema<PgcsRunSettings>& PgcsRunSettings::schema() {
  using S = PgcsRunSettings;
  static const core::SettingsSchema<S> schema(
      "pgcs",
      {core::integer_field<S>("steps", &S::steps, 1, 1e10, "exploration steps"),
       core::integer_field<S>("queries", &S::queries, 0, 1e6, "random query pairs after exploring"),
       core::integer_field<S>("curve_points", &S::curve_points, 1, 1e5, "samples of the exploration curves"),
       core::choice_field<S>("exploration", &S::exploration, {"random-walk", "novelty"},
                             "random-walk (the paper) or novelty (heads for the least visited clear direction)"),
       core::real_field<S>("speed", &S::speed, 1e-3, 1, "robot radii per time step"),
       core::real_field<S>("turn_every", &S::turn_every, 1, 1e9, "random walk: mean steps between turns"),
       core::real_field<S>("avoid_distance", &S::avoid_distance, 0, 100, "radii: a closer reading ahead turns the walk"),
       core::real_field<S>("sensor_range", &S::sensor_range, 1e-3, 100, "radii beyond the rim"),
       core::real_field<S>("sensor_noise", &S::sensor_noise, 0, 10, "radii, standard deviation of a reading"),
       core::real_field<S>("turn_weight", &S::turn_weight, 0, 1e6, "route cost per radian turned, in radii"),
       core::real_field<S>("prior_weight", &S::prior_weight, 0, 1e6, "route cost per log(mean prior / prior), radii"),
       core::integer_field<S>("attach", &S::attach, 1, 64, "start and target join this many nearest centres"),
       core::integer_field<S>("max_replans", &S::max_replans, 0, 1e6, "a query gives up after this many replans"),
       core::real_field<S>("block_distance", &S::block_distance, 0, 100, "radii: a closer reading ahead is a block"),
       core::real_field<S>("reference_cell", &S::reference_cell, 0, 1e9,
                           "m, cell of the reference grid (0: longer side / 256)"),
       core::real_field<S>("detour", &S::detour, 0, 1e6,
                           "radii a leg may slide off its line past what blocks it (0: stop at the first block)"),
       core::integer_field<S>("strikes", &S::strikes, 1, 1000,
                              "blocks before an edge is illegal (1: the paper; more: a suspect edge is a last resort first)"),
       core::real_field<S>("suspect_weight", &S::suspect_weight, 0, 1e9,
                           "extra route cost per length of an edge blocked fewer than `strikes` times"),
       core::bool_field<S>("retreat", &S::retreat, "after a block, drive back the way the leg came before replanning"),
       core::bool_field<S>("portals", &S::portals,
                           "drive an edge through where the explorer crossed between its clusters"),
       core::real_field<S>("unverified_weight", &S::unverified_weight, 0, 1e6,
                           "extra route cost per length of an edge the explorer never crossed (needs portals)"),
       core::bool_field<S>("exemplars", &S::exemplars,
                           "drive to the visited position nearest each centre instead of the centre"),
       core::bool_field<S>("shortcuts", &S::shortcuts,
                           "between two portals, cut across the cell instead of through its point"),
       core::bool_field<S>("trace_legs", &S::trace_legs,
                           "drive a route along where the robot has stood in its clusters' cells")});
  return schema;
}

PgcsSession::PgcsSession(NavTask task, PgcsRunSettings run, learn::PgcsSettings pgcs, std::uint64_t seed)
    : task_(std::move(task)),
      run_((run.validate(), run)),
      pgcs_(pgcs),
      memory_(task_.robot_radius, run_.strikes),
      portals_(pgcs.window),
      planner_(RouteSettings{run_.turn_weight * task_.robot_radius, run_.prior_weight * task_.robot_radius, run_.attach,
                             run_.portals ? run_.unverified_weight : 0.0, run_.suspect_weight}),
      explore_rng_(core::derive_seed(seed, kExplore)),
      query_rng_(core::derive_seed(seed, kQueries)),
      drive_rng_(core::derive_seed(seed, kDrive)),
      simulator_(make_simulator(task_, run_)),
      walk_(walk_settings(task_, run_),
            [this](const Eigen::Vector2d& p) {
              // How visited p is: minus its distance to the nearest centre. (The mixture density
              // would underflow to 0 a few sigma out, leaving every unexplored direction tied.)
              const int k = pgcs_.triangulation().nearest(p);
              return k < 0 ? 0.0 : -(p - pgcs_.mean(k)).norm();
            }),
      reference_(*task_.timeline->base(), task_.robot_radius, run_.reference_cell),
      trace_(trace_raster(reference_.mask(), task_.robot_radius)) {
  base_reachable_ = reference_.reachable_from(task_.start);
  if (std::none_of(base_reachable_.begin(), base_reachable_.end(), [](std::uint8_t c) { return c != 0; })) {
    throw ParameterError("no free cell of the reference grid is reachable from the start (the world has no room "
                         "for the robot, or reference_cell is too coarse)");
  }
}

PgcsSession::~PgcsSession() = default;

bool PgcsSession::explore(long steps, const core::StopCondition* stop, const std::function<void(long)>& progress) {
  const long sample_every = std::max(1L, run_.steps / run_.curve_points);
  const long trace_every = std::max(1L, run_.steps / kTracePoints);
  if (curves_.empty()) curves_.push_back(sample());
  for (long i = 0; i < steps; ++i) {
    if (stop != nullptr && (i & 255) == 0 && stop->time_up()) return false;
    const Eigen::Vector2d command = walk_.command(simulator_, last_blocked_, explore_rng_);
    const Eigen::Vector2d before = simulator_.state().position;
    last_blocked_ = simulator_.step(command, explore_rng_).blocked;
    pgcs_.step(simulator_.state().position);
    trace_.visit(before, simulator_.state().position);
    ++explore_steps_;
    track_clusters();
    if (explore_steps_ % trace_every == 0) explored_.push_back(simulator_.state().position);
    if (explore_steps_ % sample_every == 0 || i + 1 == steps) {
      if (curves_.back().step != explore_steps_) curves_.push_back(sample());
      if (progress) progress(i + 1);
    }
  }
  return true;
}

void PgcsSession::track_clusters() {
  const long n = pgcs_.steps();
  const learn::PgcsSettings& ps = pgcs_.settings();
  if (n == 1 || n % ps.insert_every == 0 || n % ps.delete_every == 0) {
    std::fill(alive_.begin(), alive_.end(), 0);
    for (int k : pgcs_.ids()) {
      const auto id = static_cast<std::size_t>(k);
      if (id >= born_.size()) {
        born_.resize(id + 1, -1), alive_.resize(id + 1, 0);
        exemplar_.resize(id + 1, Eigen::Vector2d::Zero()), exemplar_born_.resize(id + 1, -1);
      }
      if (born_[id] < 0 || (!was_alive_.empty() && (id >= was_alive_.size() || !was_alive_[id]))) {
        if (born_[id] >= 0) portals_.forget(k);  // the id is reused: its old pairs are not this cluster's
        born_[id] = n;
      }
      alive_[id] = 1;
    }
    for (std::size_t id = 0; id < was_alive_.size(); ++id) {
      if (was_alive_[id] != 0 && alive_[id] == 0) portals_.forget(static_cast<int>(id));  // deleted
    }
    was_alive_ = alive_;
  }
  // The Voronoi cell the robot stands in (its nearest centre), not the PGCS winner: the planning
  // graph is the Delaunay graph, the dual of these cells, so a move from one cell into another is
  // the evidence for that very edge (the winner, whose criterion weighs sigma and pi, may be a
  // wide cluster far off, and its "crossings" would join clusters that are not neighbours).
  const int w = pgcs_.triangulation().nearest(simulator_.state().position);
  const Eigen::Vector2d& x = simulator_.state().position;
  if (w >= 0 && static_cast<std::size_t>(w) < born_.size()) {
    const auto uw = static_cast<std::size_t>(w);
    if (exemplar_born_[uw] != born_[uw] ||
        (x - pgcs_.mean(w)).squaredNorm() < (exemplar_[uw] - pgcs_.mean(w)).squaredNorm()) {
      exemplar_[uw] = x;
      exemplar_born_[uw] = born_[uw];
    }
  }
  if (run_.portals && w >= 0 && last_winner_ >= 0 && w != last_winner_ && alive_[static_cast<std::size_t>(last_winner_)]) {
    portals_.observe(last_winner_, born_[static_cast<std::size_t>(last_winner_)], w, born_[static_cast<std::size_t>(w)],
                     0.5 * (x + last_position_));
  }
  last_winner_ = w;
  last_position_ = x;
}

const Eigen::Vector2d* PgcsSession::portal(int a, int b) const {
  if (!run_.portals) return nullptr;
  const auto ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(b);
  if (ua >= born_.size() || ub >= born_.size()) return nullptr;
  return portals_.find(a, born_[ua], b, born_[ub]);
}

Eigen::Vector2d PgcsSession::node_point(int k) const {
  const auto u = static_cast<std::size_t>(k);
  if (!run_.exemplars) return pgcs_.mean(k);
  // A cluster whose cell the robot has not entered since it was made has no exemplar: nothing says the robot
  // can stand in it, so routes leave it out.
  if (u >= born_.size() || exemplar_born_[u] != born_[u]) return Eigen::Vector2d::Constant(std::nan(""));
  return exemplar_[u];
}

const std::vector<std::uint8_t>& PgcsSession::reachable() {
  const std::size_t version = task_.timeline->version_at(simulator_.step_count());
  if (version != current_version_) {
    current_ = std::make_unique<ReferenceGrid>(*task_.timeline->at(simulator_.step_count()), task_.robot_radius,
                                               reference_.mask().cell_size());
    current_reachable_ = current_->reachable_from(task_.start);
    current_version_ = version;
  }
  return current_reachable_;
}

std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> PgcsSession::draw_queries(int count) {
  const std::vector<std::uint8_t>& open = reachable();
  std::vector<int> cells;
  for (std::size_t i = 0; i < open.size(); ++i) {
    if (open[i] != 0) cells.push_back(static_cast<int>(i));
  }
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> out;
  const FreeMask& m = current_->mask();
  for (int q = 0; q < count && !cells.empty(); ++q) {
    const int a = cells[query_rng_.uniform_index(cells.size())];
    const int b = cells[query_rng_.uniform_index(cells.size())];
    out.emplace_back(m.cell_center(a), m.cell_center(b));
  }
  return out;
}

void PgcsSession::adopt_exemplars() {
  // A cluster born late may never have had the robot in its cell since, though the robot stood there
  // before (under other clusters): such cells would drop out of every route, and with them whole
  // rooms on a large map (12% of 1,000 clusters on the MovingAI rooms map). The kept exploration
  // trace (an even subsample of every position) gives them an exemplar where it can.
  for (const Eigen::Vector2d& p : explored_) {
    const int k = pgcs_.triangulation().nearest(p);
    if (k < 0) continue;
    const auto u = static_cast<std::size_t>(k);
    if (exemplar_born_[u] != born_[u] || (p - pgcs_.mean(k)).squaredNorm() < (exemplar_[u] - pgcs_.mean(k)).squaredNorm()) {
      exemplar_[u] = p;
      exemplar_born_[u] = born_[u];
    }
  }
  exemplars_step_ = pgcs_.steps();
}

}  // namespace amp::nav
