#include "amp/roadmap/path_certificate.hpp"

#include "amp/core/counters.hpp"
#include "amp/core/stop_condition.hpp"
#include "amp/roadmap/local_planners/edge_certifier.hpp"
#include "amp/world/validity_checker.hpp"

namespace amp::roadmap {

PathCertificate certify_path(const core::Space& space, const world::CheckerFactory& world,
                             const std::vector<State>& path, double time_limit_s) {
  if (path.empty()) return {false, "the path has no waypoint"};
  core::Counters counters;
  const auto checker = world.make_checker(counters);
  const core::StopCondition stop(time_limit_s, std::numeric_limits<std::size_t>::max());
  EdgeCertifier certifier(space, *checker, &stop);
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (!checker->is_valid(path[i])) return {false, "waypoint " + std::to_string(i) + " is in collision"};
  }
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    if (certifier.certify(path[i], path[i + 1])) continue;
    if (stop.fired()) {
      return {false, "the check stopped at its time limit (" + std::to_string(static_cast<int>(time_limit_s)) +
                         " s) at segment " + std::to_string(i)};
    }
    return {false, "segment " + std::to_string(i) + " (waypoints " + std::to_string(i) + " to " +
                       std::to_string(i + 1) + ") could not be certified"};
  }
  return {true, {}};
}

}  // namespace amp::roadmap
