#pragma once
#include <string>

namespace amp::core {

// How a planner checks the edges it adds (problem field `edge_check`).
//   kDiscrete:  states at the space's resolution along each edge (the papers' CD-call cost measure);
//               the solution path is certified before it is reported, and an edge that fails is
//               removed and planning goes on (as Lazy PRM does with invalid edges).
//   kCertified: every edge is certified by conservative advancement when it is added.
// Either way, a path reported as solved is certified collision-free.
enum class EdgeCheckMode { kDiscrete, kCertified };

// "discrete" / "certified"; throws ParameterError otherwise.
EdgeCheckMode parse_edge_check_mode(const std::string& text);
const char* to_string(EdgeCheckMode mode);

}  // namespace amp::core
