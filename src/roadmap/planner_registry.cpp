#include "amp/roadmap/planner_registry.hpp"

#include <stdexcept>

#include "amp/core/error.hpp"
#include "amp/roadmap/competence/competence_prm.hpp"
#include "amp/roadmap/uas/hybrid_prm.hpp"
#include "amp/roadmap/uas/uas.hpp"
#include "amp/roadmap/catalog/sampler_prms.hpp"

namespace amp::roadmap {

void PlannerRegistry::add(PlannerInfo info, Factory factory) {
  std::string name = info.name;
  if (!entries_.emplace(name, Entry{std::move(info), std::move(factory)}).second) {
    throw std::logic_error("planner '" + name + "' registered twice");
  }
}

const PlannerRegistry::Entry& PlannerRegistry::entry(const std::string& name) const {
  const auto it = entries_.find(name);
  if (it == entries_.end()) {
    std::string valid;
    for (const auto& [n, e] : entries_) valid += (valid.empty() ? "" : ", ") + n;
    throw ParameterError("unknown planner '" + name + "' (valid: " + valid + ")");
  }
  return it->second;
}

std::unique_ptr<Planner> PlannerRegistry::make(const std::string& name, const ParamMap& params) const {
  const Entry& e = entry(name);
  return e.factory(Params(name, e.info.params, params));
}

const PlannerInfo& PlannerRegistry::info(const std::string& name) const { return entry(name).info; }

std::vector<std::string> PlannerRegistry::names() const {
  std::vector<std::string> out;
  for (const auto& [n, e] : entries_) out.push_back(n);
  return out;
}

const PlannerRegistry& builtin_planners() {
  // A function-local constant, not mutable global state: built once (thread-safe), never changed.
  static const PlannerRegistry registry = [] {
    PlannerRegistry r;
    register_prm(r);
    register_sampler_prms(r);
    register_hybrid_prm(r);
    register_uas(r);
    register_competence_prms(r);
    register_rrt_connect(r);
    return r;
  }();
  return registry;
}

}  // namespace amp::roadmap
