#pragma once
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "amp/roadmap/parameters.hpp"
#include "amp/roadmap/planner.hpp"

namespace amp::roadmap {

// What `amp bench --list` prints about a planner.
struct PlannerInfo {
  std::string name;
  std::string help;
  std::vector<ParamSpec> params;
};

// Planner name -> factory. Parameters are checked against the planner's ParamSpecs before its
// factory runs, so factories read typed, in-range values.
class PlannerRegistry {
 public:
  using Factory = std::function<std::unique_ptr<Planner>(const Params&)>;

  // Throws std::logic_error for a duplicate name (a programming error).
  void add(PlannerInfo info, Factory factory);

  // Throws ParameterError for an unknown planner (listing the valid names) or a bad parameter.
  std::unique_ptr<Planner> make(const std::string& name, const ParamMap& params) const;
  // Throws ParameterError for an unknown planner.
  const PlannerInfo& info(const std::string& name) const;
  bool contains(const std::string& name) const { return entries_.count(name) != 0; }
  // Sorted names.
  std::vector<std::string> names() const;

 private:
  struct Entry {
    PlannerInfo info;
    Factory factory;
  };
  const Entry& entry(const std::string& name) const;
  std::map<std::string, Entry> entries_;
};

// Every planner of the library, built once on first use and immutable afterwards.
const PlannerRegistry& builtin_planners();

// Adds `prm` (see prm.hpp) to a registry.
void register_prm(PlannerRegistry& registry);
// Adds `rrt-connect` (see rrt_connect.hpp) to a registry.
void register_rrt_connect(PlannerRegistry& registry);

}  // namespace amp::roadmap
