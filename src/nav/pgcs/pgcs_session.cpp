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

}  // namespace

PgcsSession::PgcsSession(NavTask task, PgcsRunSettings run, learn::PgcsSettings pgcs, std::uint64_t seed)
    : task_(std::move(task)),
      run_((run.validate(), run)),
      explorer_(task_, run_, pgcs, core::Rng(core::derive_seed(seed, kExplore))),
      simulator_(make_simulator(task_, run_)),
      worlds_(task_, run_.reference_cell),
      trace_(trace_raster(worlds_.base().mask(), task_.robot_radius)),
      router_(run_, task_.robot_radius, explorer_, trace_),
      driver_(run_, task_.robot_radius, core::Rng(core::derive_seed(seed, kDrive)), simulator_, trace_, worlds_,
              explorer_, router_),
      query_rng_(core::derive_seed(seed, kQueries)) {
  if (!worlds_.start_has_room()) {
    throw ParameterError("no free cell of the reference grid is reachable from the start (the world has no room "
                         "for the robot, or reference_cell is too coarse)");
  }
}

PgcsSession::~PgcsSession() = default;

bool PgcsSession::explore(long steps, const core::StopCondition* stop, const std::function<void(long)>& progress) {
  const long sample_every = std::max(1L, run_.steps / run_.curve_points);
  if (curves_.empty()) curves_.push_back(sample());
  for (long i = 0; i < steps; ++i) {
    if (stop != nullptr && (i & 255) == 0 && stop->time_up()) return false;
    explorer_.step(simulator_, trace_);
    if (explorer_.steps() % sample_every == 0 || i + 1 == steps) {
      if (curves_.back().step != explorer_.steps()) curves_.push_back(sample());
      if (progress) progress(i + 1);
    }
  }
  return true;
}

CurvePoint PgcsSession::sample() {
  CurvePoint c;
  c.step = explorer_.steps();
  c.clusters = explorer_.clusters().size();
  c.coverage = coverage();
  c.quantisation_error = quantisation_error();
  // Clusters whose centre the robot could reach in the world it started in but no longer can.
  c.closed_prior = worlds_.closed_prior(explorer_.clusters(), simulator_.step_count());
  return c;
}

double PgcsSession::coverage() const { return worlds_.coverage(explorer_.clusters()); }

double PgcsSession::quantisation_error() const { return worlds_.quantisation_error(explorer_.clusters()); }

std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> PgcsSession::draw_queries(int count) {
  const std::vector<std::uint8_t>& open = worlds_.reachable_at(simulator_.step_count());
  std::vector<int> cells;
  for (std::size_t i = 0; i < open.size(); ++i) {
    if (open[i] != 0) cells.push_back(static_cast<int>(i));
  }
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> out;
  const FreeMask& m = worlds_.now().mask();
  for (int q = 0; q < count && !cells.empty(); ++q) {
    const int a = cells[query_rng_.uniform_index(cells.size())];
    const int b = cells[query_rng_.uniform_index(cells.size())];
    out.emplace_back(m.cell_center(a), m.cell_center(b));
  }
  return out;
}

QueryRecord PgcsSession::query(const Eigen::Vector2d& start, const Eigen::Vector2d& target,
                               const core::StopCondition* stop) {
  return driver_.query(start, target, stop);
}

}  // namespace amp::nav
