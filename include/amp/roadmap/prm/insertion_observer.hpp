#pragma once
#include <cstddef>
#include <map>
#include <string>

#include "amp/roadmap/roadmap.hpp"

namespace amp::roadmap {

// What happened when PRM inserted a vertex: its connection attempts (to the candidates of the
// connection strategy, the k nearest by default) and how many distinct components it joined.
struct Insertion {
  VertexId vertex = 0;
  bool seed = false;                   // a start/goal/task seed, not a sample
  std::size_t attempts = 0;            // local-planner calls (lazy PRM: edges added unchecked)
  std::size_t successes = 0;           // edges added
  std::size_t components_joined = 0;   // distinct components the vertex connected to (0 = a new one)

  // Visibility (UAS): successes / attempts. A vertex with no attempt had no neighbour at all (the
  // roadmap was empty): nothing around it was seen to block it, so we take free space around it as
  // open and its visibility as 1 (docs/uas.md), which costs no extra CD call.
  double visibility() const {
    return attempts == 0 ? 1.0 : static_cast<double>(successes) / static_cast<double>(attempts);
  }
};

// Told about every vertex a PRM run inserts, right after its connections were tried (the sample's
// structural effect is then known: UAS rewards, node classes). Observing changes nothing in the run.
class InsertionObserver {
 public:
  virtual ~InsertionObserver() = default;
  virtual void inserted(const Roadmap& roadmap, const Insertion& insertion) = 0;
  // Adds the observer's per-run figures to PlanResult::extra.
  virtual void report(std::map<std::string, double>& /*extra*/) const {}
};

}  // namespace amp::roadmap
