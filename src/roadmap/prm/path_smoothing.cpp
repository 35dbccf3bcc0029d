#include "amp/roadmap/prm/path_smoothing.hpp"

#include <utility>

namespace amp::roadmap {

double path_length(const core::Space& space, const std::vector<State>& path) {
  double sum = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) sum += space.distance(path[i - 1], path[i]);
  return sum;
}

int shortcut_path(LocalPlanner& local_planner, core::Rng& rng, int attempts, std::vector<State>& path,
                  const core::StopCondition* stop) {
  int taken = 0;
  for (int a = 0; a < attempts && path.size() >= 3; ++a) {
    if (stop != nullptr && stop->time_up()) break;
    std::size_t i = rng.uniform_index(path.size());
    std::size_t j = rng.uniform_index(path.size());
    if (i > j) std::swap(i, j);
    if (j - i < 2) continue;  // neighbours already share an edge: nothing to cut
    if (local_planner.connect(path[i], path[j])) {
      path.erase(path.begin() + static_cast<std::ptrdiff_t>(i + 1), path.begin() + static_cast<std::ptrdiff_t>(j));
      ++taken;
    }
  }
  return taken;
}

}  // namespace amp::roadmap
