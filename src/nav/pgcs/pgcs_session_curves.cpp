// PgcsSession's exploration curves: coverage, quantisation error and the prior of clusters a
// changed world has cut off, sampled as the exploration goes.
#include <algorithm>
#include <cmath>

#include "amp/nav/pgcs/pgcs_session.hpp"

namespace amp::nav {

namespace {
// At most this many reachable cells enter the quantisation error (an even stride over them).
constexpr std::size_t kErrorCells = 4096;
}  // namespace

CurvePoint PgcsSession::sample() {
  CurvePoint c;
  c.step = explore_steps_;
  c.clusters = pgcs_.size();
  c.coverage = coverage();
  c.quantisation_error = quantisation_error();
  // Clusters whose centre the robot could reach in the world it started in but no longer can. (A
  // centre is a mean of positions and may itself lie where the disc does not fit, beside a wall:
  // such a cluster is counted by where the robot can stand nearest to it, cell_near.)
  const std::vector<std::uint8_t>& open = reachable();
  if (current_version_ == 0) return c;
  for (int k : pgcs_.ids()) {
    const int cell = reference_.cell_near(pgcs_.mean(k));
    if (cell >= 0 && base_reachable_[static_cast<std::size_t>(cell)] != 0 && open[static_cast<std::size_t>(cell)] == 0) {
      c.closed_prior += pgcs_.prior(k);
    }
  }
  return c;
}

double PgcsSession::coverage() const {
  const FreeMask& m = reference_.mask();
  std::vector<std::uint8_t> covered(m.cell_count(), 0);
  const std::size_t open = static_cast<std::size_t>(std::count(base_reachable_.begin(), base_reachable_.end(), 1));
  // Widest first, stopping once every reachable cell is covered: early in an exploration a few
  // clusters span the whole map, and stamping each of them cell by cell would dominate the run.
  std::vector<int> order(pgcs_.ids().begin(), pgcs_.ids().end());
  std::sort(order.begin(), order.end(), [&](int a, int b) { return pgcs_.variance(a) > pgcs_.variance(b); });
  std::size_t hit = 0;
  for (int k : order) {
    if (hit == open) break;
    const double reach = 2.0 * std::sqrt(pgcs_.variance(k));
    const Eigen::Vector2d lo = (pgcs_.mean(k) - m.origin()).array() / m.cell_size() - reach / m.cell_size();
    const Eigen::Vector2d hi = (pgcs_.mean(k) - m.origin()).array() / m.cell_size() + reach / m.cell_size();
    const int x0 = std::max(0, static_cast<int>(std::floor(lo.x()))), x1 = std::min(m.width() - 1, static_cast<int>(hi.x()));
    const int y0 = std::max(0, static_cast<int>(std::floor(lo.y()))), y1 = std::min(m.height() - 1, static_cast<int>(hi.y()));
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const auto cell = static_cast<std::size_t>(m.index(x, y));
        if (covered[cell] == 0 && (m.cell_center(x, y) - pgcs_.mean(k)).squaredNorm() <= reach * reach) {
          covered[cell] = 1;
          hit += base_reachable_[cell];
        }
      }
    }
  }
  return open == 0 ? 0.0 : static_cast<double>(hit) / static_cast<double>(open);
}

double PgcsSession::quantisation_error() const {
  if (pgcs_.size() == 0) return 0.0;
  const FreeMask& m = reference_.mask();
  const std::size_t open = static_cast<std::size_t>(std::count(base_reachable_.begin(), base_reachable_.end(), 1));
  const std::size_t stride = std::max<std::size_t>(1, (open + kErrorCells - 1) / kErrorCells);
  double sum = 0.0;
  std::size_t n = 0, seen = 0;
  for (std::size_t i = 0; i < base_reachable_.size(); ++i) {
    if (base_reachable_[i] == 0 || seen++ % stride != 0) continue;
    const Eigen::Vector2d p = m.cell_center(static_cast<int>(i));
    sum += (pgcs_.mean(pgcs_.triangulation().nearest(p)) - p).squaredNorm();
    ++n;
  }
  return std::sqrt(sum / static_cast<double>(n));
}

}  // namespace amp::nav
