#pragma once
#include <string>
#include <vector>

#include "amp/core/space.hpp"
#include "amp/core/state.hpp"
#include "amp/world/checker_factory.hpp"

namespace amp::roadmap {

// Whether a whole path is collision-free: every waypoint valid and every segment between two
// consecutive waypoints certified by EdgeCertifier (conservative advancement), the guarantee a
// solved run's path carries. A path read from a file (`amp view --path`) is checked so before a
// page calls it certified.
struct PathCertificate {
  bool certified = false;
  // Why not, in words: "waypoint 3 is in collision", "segment 4 (waypoints 4 to 5) could not be
  // certified", or "the check stopped at its time limit (30 s) at segment 12". Empty when certified.
  std::string failure;
};

// Stops after `time_limit_s` (the proof of a grazing segment may take long); a stopped proof is
// not a certificate. An empty path is not certified.
PathCertificate certify_path(const core::Space& space, const world::CheckerFactory& world,
                             const std::vector<State>& path, double time_limit_s = 30.0);

}  // namespace amp::roadmap
