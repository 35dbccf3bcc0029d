#pragma once
#include <functional>
#include <memory>

#include "amp/core/settings_schema.hpp"
#include "amp/roadmap/prm/connection_strategy.hpp"
#include "amp/roadmap/prm/insertion_observer.hpp"
#include "amp/roadmap/local_planners/local_planner.hpp"
#include "amp/roadmap/planner.hpp"
#include "amp/roadmap/samplers/sampler.hpp"

namespace amp::roadmap {

// The largest k (neighbours tried per new node) of every planner: beyond it, a roadmap is dense.
inline constexpr int kMaxNeighbours = 1000;

struct PrmSettings {
  int k = 10;  // neighbours tried per new vertex
  // Lazy PRM (Bohlin & Kavraki 2000): edges are added unchecked and checked only when they lie on a
  // candidate path; an invalid one is removed and the search repeated.
  bool lazy = false;
  // Kavraki et al. 1996 skip a neighbour already in the new vertex's component (a forest, fewer CD
  // calls). Off by default, as in OMPL's PRM: every one of the k nearest is tried, so a node's
  // visibility (successful / attempted connections, used by UAS) is measured over all k.
  bool skip_same_component = false;
  bool smooth = false;       // shortcut the solution path
  int smooth_attempts = 100;  // shortcut attempts per seed-to-seed segment
  // Names, ranges and help of the fields above, as `prm` takes them.
  static const core::SettingsSchema<PrmSettings>& schema();
  void validate() const { schema().validate(*this); }  // throws ParameterError
};

// A sampler and the observer that feeds it what its samples did; the observer may refer to the
// sampler, which outlives it in a run.
struct ObservedSampler {
  std::unique_ptr<Sampler> sampler;
  std::unique_ptr<InsertionObserver> observer;
};

// The policies a PRM is composed of, made afresh for every plan() call from its context (each holds
// per-run scratch and counts into the context's checker). Empty members take the defaults: uniform
// sampling, straight-line edges, k nearest by KD-tree.
struct PrmParts {
  std::function<std::unique_ptr<Sampler>(const PlanningContext&)> sampler;
  std::function<std::unique_ptr<LocalPlanner>(const PlanningContext&)> local_planner;
  std::function<std::unique_ptr<ConnectionStrategy>(const PlanningContext&)> connection;
  // Optional: told about every insertion (node classes); its report() goes into PlanResult::extra.
  std::function<std::unique_ptr<InsertionObserver>(const PlanningContext&)> observer;
  // Optional, in place of sampler and observer: a sampler that learns from its samples and the
  // observer that teaches it, made together so that neither has to guess the other's type (Hybrid
  // PRM, UAS).
  std::function<ObservedSampler(const PlanningContext&)> observed_sampler;
  // Optional: a roadmap of free vertices and checked edges built earlier in the same run (UAS's
  // training roadmap) that the run starts from, so that work is not paid twice. Its vertices count
  // towards the node limit; the observer is not told about them.
  std::shared_ptr<const Roadmap> initial;
};

// Probabilistic roadmap (Kavraki, Svestka, Latombe & Overmars 1996): sample free states, connect
// each to its candidates, stop once every seed lies in one component, then answer by A*. Seeds are
// added first, so easy queries are solved with no sample. With lazy = true this is Lazy PRM.
class Prm final : public Planner {
 public:
  explicit Prm(PrmSettings settings = {}, PrmParts parts = {});
  PlanResult plan(const PlanningContext& ctx, const core::StopCondition& stop, core::Rng& rng) override;
  const PrmSettings& settings() const { return settings_; }

 private:
  PrmSettings settings_;
  PrmParts parts_;
};

}  // namespace amp::roadmap
