#pragma once
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>

#include "amp/roadmap/prm/insertion_observer.hpp"

namespace amp::roadmap {

// A new node's effect on the roadmap's connected components (UAS; Morales et al. 2004's node types).
enum class NodeClass : std::uint8_t {
  kCreate = 0,      // connects to nothing: a new component
  kMerge = 1,       // joins two or more components
  kExpand = 2,      // joins one component and is not visible from most of its neighbours: extends its reach
  kOversample = 3,  // joins one component and is visible from most of them: adds no reach
};
inline constexpr int kNodeClassCount = 4;

// "Most of its neighbours": a node joining one component is cc-expand when its visibility (connection
// successes / attempts) is below one half, i.e. it failed to see the majority of its neighbours.
inline constexpr double kExpandVisibility = 0.5;

NodeClass classify(const Insertion& insertion);
// "cc_create", "cc_merge", "cc_expand", "cc_oversample" (the PlanResult::extra keys).
std::string_view to_string(NodeClass c);

// Per-run counts of the classes of sampled nodes (seeds are not samples and are not counted).
// `constants` are run figures known up front (e.g. the sampler distance), reported as they are.
class NodeClassCounter final : public InsertionObserver {
 public:
  explicit NodeClassCounter(std::map<std::string, double> constants = {}) : constants_(std::move(constants)) {}
  void inserted(const Roadmap& roadmap, const Insertion& insertion) override;
  // cc_create, cc_merge, cc_expand, cc_oversample.
  void report(std::map<std::string, double>& extra) const override;
  std::uint64_t count(NodeClass c) const { return counts_[static_cast<int>(c)]; }

 private:
  std::map<std::string, double> constants_;
  std::array<std::uint64_t, kNodeClassCount> counts_{};
};

}  // namespace amp::roadmap
