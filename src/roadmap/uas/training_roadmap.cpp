#include "amp/roadmap/uas/training_roadmap.hpp"

#include <string>

#include "amp/core/error.hpp"
#include "amp/roadmap/prm/prm.hpp"
#include "amp/roadmap/samplers/gaussian_sampler.hpp"
#include "amp/roadmap/prm/insertion_observer.hpp"
#include "amp/roadmap/neighbors/kd_tree_neighbors.hpp"
#include "amp/roadmap/samplers/obprm_sampler.hpp"
#include "amp/roadmap/samplers/random_offset.hpp"
#include "amp/roadmap/local_planners/straight_line_planner.hpp"
#include "amp/roadmap/samplers/uniform_domain_sampler.hpp"

namespace amp::roadmap {

namespace {
constexpr int kMaxTrainingNodes = 100000;
}  // namespace

const core::SettingsSchema<TrainingSettings>& TrainingSettings::schema() {
  using S = TrainingSettings;
  static const core::SettingsSchema<S> schema(
      "uas", {core::integer_field<S>("training_nodes", &S::nodes, 2, kMaxTrainingNodes, "training roadmap size"),
              core::integer_field<S>("training_k", &S::k, 1, kMaxNeighbours, "neighbours per training node"),
              core::enum_field<S>(
                  "training_visibility", &S::visibility,
                  std::vector<std::pair<std::string, TrainingVisibility>>{{"insertion", TrainingVisibility::kInsertion},
                                                                          {"all", TrainingVisibility::kAllAttempts}},
                  "a training node's visibility: its own attempts at insertion, or all attempts it took part in")});
  return schema;
}

void TrainingSettings::validate() const {
  schema().validate(*this);
  if (attempts_per_node < 1) throw ParameterError("uas: attempts_per_node must be >= 1");
}

Eigen::MatrixXd TrainingSet::features() const {
  const Eigen::Index n = static_cast<Eigen::Index>(size());
  Eigen::MatrixXd f(n, planar ? 3 : 4);
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto u = static_cast<std::size_t>(i);
    f(i, 0) = visibility[u];
    f(i, 1) = positions[u].x();
    f(i, 2) = positions[u].y();
    if (!planar) f(i, 3) = positions[u].z();
  }
  return f;
}

TrainingSet build_training_roadmap(const PlanningContext& ctx, const TrainingSettings& settings,
                                   const core::StopCondition& stop, core::Rng& rng) {
  settings.validate();
  const auto whole = domain_or_whole(nullptr, ctx.space);
  const double r = sampler_distance(ctx.environment, ctx.space, 1.0).d;
  UniformDomainSampler uniform(whole, ctx.checker);
  GaussianSampler gaussian(ctx.space, ctx.checker, GaussianSamplerSettings{r, 100}, whole);
  ObprmSampler obprm(ctx.space, ctx.checker, ObprmSamplerSettings{}, whole, &stop);
  Sampler* samplers[] = {&uniform, &gaussian, &obprm};

  TrainingSet set;
  set.roadmap = std::make_shared<Roadmap>();
  set.planar = ctx.environment.workspace_dimension() == 2;
  const auto wanted = static_cast<std::size_t>(settings.nodes);
  set.roadmap->reserve(wanted, 2 * static_cast<std::size_t>(settings.k));
  KdTreeNeighbors nn(ctx.space, &ctx.checker.counters());
  nn.reserve(wanted);
  StraightLinePlanner local(ctx.space, ctx.checker, &stop);  // an edge at a fine resolution stops with the training
  std::vector<Neighbor> neighbors;
  std::vector<std::size_t> tried, linked;  // per vertex, for TrainingVisibility::kAllAttempts
  tried.reserve(wanted);
  linked.reserve(wanted);
  State q;
  const std::uint64_t max_attempts = wanted * static_cast<std::uint64_t>(settings.attempts_per_node);
  std::uint64_t attempts = 0;
  std::size_t turn = 0;  // fixed proportions: uniform, Gaussian, OBPRM, uniform, ...
  while (set.size() < wanted && attempts < max_attempts) {
    set.stopped = stop.check(set.size());
    if (set.stopped != core::StopReason::kNone) break;
    ++attempts;
    const std::size_t which = turn % 3;
    if (!samplers[which]->sample(rng, q)) {
      ++set.failed_samples;
      continue;  // the same sampler tries again: the proportions stay fixed
    }
    ++turn;
    const VertexId v = set.roadmap->add_vertex(q);
    nn.k_nearest(q, static_cast<std::size_t>(settings.k), neighbors);
    Insertion info;
    for (const Neighbor& n : neighbors) {
      ++info.attempts;
      ++tried[n.index];
      if (local.connect(q, set.roadmap->state(n.index))) {
        set.roadmap->add_edge(v, n.index, n.distance);
        ++info.successes;
        ++linked[n.index];
      }
    }
    nn.add(v, q);
    tried.push_back(info.attempts);
    linked.push_back(info.successes);
    set.positions.push_back(ctx.environment.reference_point(q));
    set.visibility.push_back(info.visibility());
    set.sampler.push_back(static_cast<int>(which));
  }
  if (settings.visibility == TrainingVisibility::kAllAttempts) {
    for (std::size_t i = 0; i < set.size(); ++i) {
      set.visibility[i] = tried[i] == 0 ? 1.0 : static_cast<double>(linked[i]) / static_cast<double>(tried[i]);
    }
  }
  if (set.size() == 0 && set.stopped == core::StopReason::kNone) {
    throw Error("uas: the training roadmap found no free configuration in " + std::to_string(attempts) +
                " sampling attempts (is the free space empty?)");
  }
  return set;
}

}  // namespace amp::roadmap
