#include "amp/roadmap/competence/competence_prm.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "amp/core/error.hpp"
#include "amp/roadmap/prm/component_connection.hpp"
#include "amp/roadmap/prm/prm.hpp"

namespace amp::roadmap {

CompetentLocalPlanner::CompetentLocalPlanner(std::unique_ptr<GridAStarPlanner> astar,
                                             std::unique_ptr<CompetencePolicy> policy)
    : astar_(std::move(astar)), policy_(std::move(policy)) {}

bool CompetentLocalPlanner::connect_edge(const State& a, const State& b, const EdgeRequest& request) {
  const double o_th = policy_->threshold(request);
  astar_->set_threshold(o_th);
  const bool ok = astar_->connect(a, b);
  policy_->record(request, ok);
  if (ok && request.from != EdgeRequest::kNoVertex) astar_->last_moves(moves_[key(request)]);
  const GridSearchStats& s = astar_->last();
  ++calls_;
  cells_ += s.cells_checked;
  move_checks_ += s.move_checks;
  repairs_ += s.repairs;
  if (s.capped) ++capped_;
  if (!ok) ++(s.abandoned ? abandoned_ : exhausted_);
  threshold_sum_ += o_th;
  threshold_max_ = std::max(threshold_max_, o_th);
  return ok;
}

void CompetentLocalPlanner::edge_waypoints(const State& a, const State& b, const EdgeRequest& request,
                                           std::vector<State>& out) {
  const auto it = moves_.find(key(request));
  if (it != moves_.end()) {
    astar_->replay(a, b, it->second, out);
    return;
  }
  astar_->edge_waypoints(a, b, request, out);  // not one of ours: search again (counted)
}

void CompetentLocalPlanner::report(std::map<std::string, double>& extra) const {
  extra["astar_calls"] = static_cast<double>(calls_);
  extra["astar_abandoned"] = static_cast<double>(abandoned_);   // stopped by O_th (or max_cells)
  extra["astar_capped"] = static_cast<double>(capped_);         // of which by max_cells
  extra["astar_exhausted"] = static_cast<double>(exhausted_);   // no grid path, or b's cell blocked
  extra["astar_cells"] = static_cast<double>(cells_);
  extra["astar_move_checks"] = static_cast<double>(move_checks_);  // path moves checked at the space's resolution
  extra["astar_repairs"] = static_cast<double>(repairs_);          // searches repeated around a clipping move
  extra["threshold_mean"] = calls_ ? threshold_sum_ / static_cast<double>(calls_) : 0.0;
  extra["threshold_max"] = threshold_max_;
}

namespace {

std::unique_ptr<CompetencePolicy> make_policy(CompetenceKind kind, double value) {
  switch (kind) {
    case CompetenceKind::kStatic:
      return std::make_unique<StaticCompetence>(value);
    case CompetenceKind::kGlobal:
      return std::make_unique<GlobalCompetence>(value);
    case CompetenceKind::kLocal:
      return std::make_unique<LocalCompetence>(value);
  }
  throw std::logic_error("unknown competence kind");
}

}  // namespace

const std::vector<double>& metaplanner_values(CompetenceKind kind) {
  static const std::vector<double> o{2, 4, 8, 16, 32};
  static const std::vector<double> s{300, 1000, 3000, 9000};
  static const std::vector<double> n{0.01, 0.03, 0.1, 0.3};
  return kind == CompetenceKind::kStatic ? o : kind == CompetenceKind::kGlobal ? s : n;
}

const core::SettingsSchema<CompetencePrmSettings>& CompetencePrmSettings::schema() {
  using S = CompetencePrmSettings;
  static const core::SettingsSchema<S> schema("competence prm", [] {
    std::vector<core::SettingsField<S>> f{
        core::integer_field<S>("k", &S::k, 1, kMaxNeighbours, "nearest vertices tried per connected component")};
    for (auto& g : core::nested_fields<S>(GridAStarSettings::schema(), &S::grid)) f.push_back(std::move(g));
    return f;
  }());
  return schema;
}

void CompetencePrmSettings::validate() const {
  schema().validate(*this);
  make_policy(kind, value);  // throws for a value outside its range
}

CompetencePrm::CompetencePrm(CompetencePrmSettings settings) : settings_(settings) { settings_.validate(); }

PlanResult CompetencePrm::plan(const PlanningContext& ctx, const core::StopCondition& stop, core::Rng& rng) {
  const double value = settings_.value;
  PrmSettings prm;
  prm.k = settings_.k;
  prm.skip_same_component = true;  // k bounds the attempts per component; one edge joins it
  PrmParts parts;
  const CompetencePrmSettings s = settings_;
  parts.local_planner = [s, value](const PlanningContext& c) -> std::unique_ptr<LocalPlanner> {
    auto astar = std::make_unique<GridAStarPlanner>(c.space, c.checker, s.grid, c.stop);
    return std::make_unique<CompetentLocalPlanner>(std::move(astar), make_policy(s.kind, value));
  };
  parts.connection = [s](const PlanningContext& c) -> std::unique_ptr<ConnectionStrategy> {
    return std::make_unique<ComponentNearestConnection>(c.space, static_cast<std::size_t>(s.k));
  };
  PlanResult result = Prm(prm, std::move(parts)).plan(ctx, stop, rng);
  result.extra[competence_parameter(settings_.kind)] = value;
  return result;
}

}  // namespace amp::roadmap
