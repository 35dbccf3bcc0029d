#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "amp/core/settings_schema.hpp"
#include "amp/core/rng.hpp"
#include "amp/core/stop_condition.hpp"
#include "amp/roadmap/planner.hpp"
#include "amp/roadmap/roadmap.hpp"

namespace amp::roadmap {

// What a training node's visibility counts (its feature for clustering).
enum class TrainingVisibility : std::uint8_t {
  kInsertion = 0,  // its own k attempts when it was inserted (the paper)
  // Beyond the paper: every attempt it took part in, its own and those of later nodes that chose it
  // as a neighbour. Early nodes are measured on more than the few neighbours the roadmap then had,
  // and every node on about 2k attempts instead of k; no extra CD call.
  kAllAttempts = 1,
};

struct TrainingSettings {
  int nodes = 200;  // training roadmap size (UAS: 200; the paper's Tables 1-3 also use 100-400)
  int k = 5;        // low connection parameter: cheap, and enough to capture the topology
  // Sampling attempts allowed per wanted node before the roadmap is declared empty-handed.
  int attempts_per_node = 50;
  TrainingVisibility visibility = TrainingVisibility::kInsertion;
  // training_nodes, training_k, training_visibility, as uas takes them (attempts_per_node is internal).
  static const core::SettingsSchema<TrainingSettings>& schema();
  void validate() const;  // throws ParameterError
};

// UAS's training set (UAS study, section 4.2): a small roadmap of fixed proportions of uniform, Gaussian
// (d = r) and OBPRM nodes, each the next in turn, and per node the features clustering uses.
struct TrainingSet {
  std::shared_ptr<Roadmap> roadmap;  // free vertices, checked edges (reusable by the planning PRM)
  std::vector<Eigen::Vector3d> positions;  // the robot's reference point per vertex
  std::vector<double> visibility;          // successes / attempts (TrainingSettings::visibility says which)
  std::vector<int> sampler;                // 0 uniform, 1 Gaussian, 2 OBPRM
  bool planar = true;                      // planar world: Z is not a feature
  std::uint64_t failed_samples = 0;
  // The stop fired before `nodes` (or, in identify_regions, during clustering).
  core::StopReason stopped = core::StopReason::kNone;

  std::size_t size() const { return positions.size(); }
  // n x (3 or 4): visibility, X, Y[, Z], not yet standardised.
  Eigen::MatrixXd features() const;
};

inline constexpr const char* kTrainingSamplerNames[] = {"uniform", "gaussian_r", "obprm"};

// Builds the training roadmap with ctx.checker (so its CD calls count in the caller's phase; UAS
// sets Phase::kTraining). Stops early when `stop` fires. Throws amp::Error when no sampler produced
// a single free state (the space has no free volume the samplers can find).
TrainingSet build_training_roadmap(const PlanningContext& ctx, const TrainingSettings& settings,
                                   const core::StopCondition& stop, core::Rng& rng);

}  // namespace amp::roadmap
