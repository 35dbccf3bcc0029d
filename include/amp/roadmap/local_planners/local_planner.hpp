#pragma once
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "amp/core/state.hpp"

namespace amp::roadmap {

// What a roadmap planner knows about an edge it asks for: the vertex being inserted, the roadmap
// vertex it tries to reach, and the roadmap's size. Planners whose competence depends on the
// roadmap (PRM-G, PRM-L) read it; vertex ids are kNoVertex when the caller has none.
struct EdgeRequest {
  static constexpr std::size_t kNoVertex = static_cast<std::size_t>(-1);
  std::size_t from = kNoVertex;
  std::size_t to = kNoVertex;
  std::size_t roadmap_size = 0;
};

// Decides whether two configurations can be joined by the planner's path between them; the
// endpoints are assumed valid. Implementations: StraightLinePlanner, GridAStarPlanner (and
// CompetentLocalPlanner around it). Holds per-thread scratch (hence non-const); use one per thread.
class LocalPlanner {
 public:
  virtual ~LocalPlanner() = default;
  virtual bool connect(const State& a, const State& b) = 0;
  // The call a roadmap planner makes when it adds an edge; the default ignores the request.
  virtual bool connect_edge(const State& a, const State& b, const EdgeRequest& /*request*/) { return connect(a, b); }
  // The states strictly between a and b on the path an accepted connect_edge(a, b, request) found,
  // in order from a; empty for planners whose edges are the space's geodesic (the straight line).
  virtual void edge_waypoints(const State& /*a*/, const State& /*b*/, const EdgeRequest& /*request*/,
                              std::vector<State>& out) {
    out.clear();
  }
  // Planner-specific figures for the run record (e.g. cells searched); none by default.
  virtual void report(std::map<std::string, double>& /*extra*/) const {}
};

}  // namespace amp::roadmap
