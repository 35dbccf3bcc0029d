#include "amp/nav/pgcs/reference_worlds.hpp"

#include <algorithm>
#include <cmath>

#include "amp/learn/pgcs.hpp"
#include "amp/nav/free_mask.hpp"

namespace amp::nav {

namespace {
// At most this many reachable cells enter the quantisation error (an even stride over them).
constexpr std::size_t kErrorCells = 4096;
}  // namespace

ReferenceWorlds::ReferenceWorlds(const NavTask& task, double cell)
    : timeline_(task.timeline),
      radius_(task.robot_radius),
      start_(task.start),
      base_(*task.timeline->base(), task.robot_radius, cell) {
  base_reachable_ = base_.reachable_from(start_);
}

bool ReferenceWorlds::start_has_room() const {
  return std::any_of(base_reachable_.begin(), base_reachable_.end(), [](std::uint8_t c) { return c != 0; });
}

const std::vector<std::uint8_t>& ReferenceWorlds::reachable_at(std::size_t step) {
  const std::size_t version = timeline_->version_at(step);
  if (version != now_version_) {
    now_ = std::make_unique<ReferenceGrid>(*timeline_->at(step), radius_, base_.mask().cell_size());
    now_reachable_ = now_->reachable_from(start_);
    now_version_ = version;
  }
  return now_reachable_;
}

double ReferenceWorlds::closed_prior(const learn::Pgcs& clusters, std::size_t step) {
  // A centre is a mean of positions and may itself lie where the disc does not fit, beside a wall:
  // such a cluster is counted by where the robot can stand nearest to it (cell_near).
  const std::vector<std::uint8_t>& open = reachable_at(step);
  double closed = 0.0;
  if (now_version_ == 0) return closed;
  for (int k : clusters.ids()) {
    const int cell = base_.cell_near(clusters.mean(k));
    if (cell >= 0 && base_reachable_[static_cast<std::size_t>(cell)] != 0 && open[static_cast<std::size_t>(cell)] == 0) {
      closed += clusters.prior(k);
    }
  }
  return closed;
}

double ReferenceWorlds::coverage(const learn::Pgcs& clusters) const {
  const FreeMask& m = base_.mask();
  std::vector<std::uint8_t> covered(m.cell_count(), 0);
  const std::size_t open = static_cast<std::size_t>(std::count(base_reachable_.begin(), base_reachable_.end(), 1));
  // Widest first, stopping once every reachable cell is covered: early in an exploration a few
  // clusters span the whole map, and stamping each of them cell by cell would dominate the run.
  std::vector<int> order(clusters.ids().begin(), clusters.ids().end());
  std::sort(order.begin(), order.end(), [&](int a, int b) { return clusters.variance(a) > clusters.variance(b); });
  std::size_t hit = 0;
  for (int k : order) {
    if (hit == open) break;
    const double reach = 2.0 * std::sqrt(clusters.variance(k));
    const Eigen::Vector2d lo = (clusters.mean(k) - m.origin()).array() / m.cell_size() - reach / m.cell_size();
    const Eigen::Vector2d hi = (clusters.mean(k) - m.origin()).array() / m.cell_size() + reach / m.cell_size();
    const int x0 = std::max(0, static_cast<int>(std::floor(lo.x()))), x1 = std::min(m.width() - 1, static_cast<int>(hi.x()));
    const int y0 = std::max(0, static_cast<int>(std::floor(lo.y()))), y1 = std::min(m.height() - 1, static_cast<int>(hi.y()));
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const auto cell = static_cast<std::size_t>(m.index(x, y));
        if (covered[cell] == 0 && (m.cell_center(x, y) - clusters.mean(k)).squaredNorm() <= reach * reach) {
          covered[cell] = 1;
          hit += base_reachable_[cell];
        }
      }
    }
  }
  return open == 0 ? 0.0 : static_cast<double>(hit) / static_cast<double>(open);
}

double ReferenceWorlds::quantisation_error(const learn::Pgcs& clusters) const {
  if (clusters.size() == 0) return 0.0;
  const FreeMask& m = base_.mask();
  const std::size_t open = static_cast<std::size_t>(std::count(base_reachable_.begin(), base_reachable_.end(), 1));
  const std::size_t stride = std::max<std::size_t>(1, (open + kErrorCells - 1) / kErrorCells);
  double sum = 0.0;
  std::size_t n = 0, seen = 0;
  for (std::size_t i = 0; i < base_reachable_.size(); ++i) {
    if (base_reachable_[i] == 0 || seen++ % stride != 0) continue;
    const Eigen::Vector2d p = m.cell_center(static_cast<int>(i));
    sum += (clusters.mean(clusters.triangulation().nearest(p)) - p).squaredNorm();
    ++n;
  }
  return std::sqrt(sum / static_cast<double>(n));
}

}  // namespace amp::nav
