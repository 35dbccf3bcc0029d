#include "amp/bench/summary.hpp"

#include <cmath>
#include <optional>

#include <nlohmann/json.hpp>

#include "amp/bench/cost_metric.hpp"

#include "amp/stats/anova.hpp"
#include "amp/stats/descriptive.hpp"
#include "amp/stats/histogram.hpp"
#include "amp/stats/kruskal_wallis.hpp"
#include "amp/stats/levene_test.hpp"
#include "amp/stats/regwq.hpp"
#include "amp/stats/welch_anova.hpp"

namespace amp::bench {

namespace {

// JSON has no NaN: statistics that do not exist (n < 2, zero variance) are written as null.
nlohmann::json num(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

nlohmann::json describe_json(const std::vector<double>& x) {
  const stats::Summary s = stats::describe(x);
  nlohmann::json j = {{"n", s.n},          {"mean", num(s.mean)},     {"std", num(s.std_dev)},
                      {"cv_percent", num(s.cv_percent)}, {"min", num(s.min)}, {"q1", num(s.q1)},
                      {"median", num(s.median)},         {"q3", num(s.q3)},   {"max", num(s.max)},
                      {"ci95", {num(s.ci95_low), num(s.ci95_high)}}};
  if (!x.empty()) {
    const stats::Histogram h = stats::histogram(x);
    j["histogram"] = {{"edges", h.edges}, {"counts", h.counts}};
  }
  return j;
}

nlohmann::json test_json(const stats::TestResult& t) {
  return {{"statistic", num(t.statistic)}, {"df1", num(t.df1)}, {"df2", num(t.df2)}, {"p_value", num(t.p_value)},
          {"status", std::string(stats::to_string(t.status))}};
}

nlohmann::json tests_json(const Experiment& e, const std::vector<GroupMetrics>& groups, double alpha) {
  const std::string& metric = e.cost;
  // Tests on samples that silently lost runs would compare survivors: say which runs lack the metric.
  std::string missing;
  for (std::size_t c = 0; c < groups.size(); ++c) {
    if (groups[c].cost_missing == 0) continue;
    missing += (missing.empty() ? "" : ", ") + std::to_string(groups[c].cost_missing) + " of '" +
               e.planners[c].label + "'";
  }
  if (!missing.empty()) {
    return {{"metric", metric}, {"skipped", "metric '" + metric + "' missing in runs (" + missing + ")"}};
  }
  stats::Groups cost;
  for (const auto& g : groups) cost.push_back(g.cost);
  for (const auto& g : cost) {
    if (g.size() < 2) {
      if (metric == kDefaultCost) return {{"skipped", "every planner needs at least two runs"}};
      return {{"metric", metric}, {"skipped", "every planner needs at least two runs with a value of '" + metric + "'"}};
    }
  }
  nlohmann::json j;
  j["metric"] = metric;
  j["direction"] = std::string(to_string(e.cost_direction));  // for REGWQ's subsets, ordered by ascending mean
  j["levene_brown_forsythe"] = test_json(stats::levene_test(cost, stats::LeveneCenter::kMedian));
  j["anova"] = test_json(stats::one_way_anova(cost).test);
  j["welch_anova"] = test_json(stats::welch_anova(cost));
  j["kruskal_wallis"] = test_json(stats::kruskal_wallis(cost));
  const stats::RegwqResult r = stats::regwq(cost, alpha);
  nlohmann::json subsets = nlohmann::json::array();
  for (const auto& s : r.subsets) {
    nlohmann::json names = nlohmann::json::array();
    for (std::size_t g : s) names.push_back(e.planners[g].label);
    subsets.push_back(names);
  }
  nlohmann::json pairs = nlohmann::json::array();
  for (std::size_t a = 0; a < groups.size(); ++a) {
    for (std::size_t b = a + 1; b < groups.size(); ++b) {
      pairs.push_back({{"a", e.planners[a].label}, {"b", e.planners[b].label},
                       {"differs", r.status == stats::TestStatus::kOk && r.differs[a][b]}});
    }
  }
  j["regwq"] = {{"alpha", alpha}, {"status", std::string(stats::to_string(r.status))}, {"subsets", subsets},
                {"pairs", pairs}, {"mse", num(r.mse)}, {"df_error", num(r.df_error)}};
  return j;
}

// The method with the best mean cost under the experiment's direction (the first of equals), or
// nothing when fewer than two methods have a mean: what the report marks, said once for every reader.
nlohmann::json best_json(const Experiment& e, const std::vector<GroupMetrics>& groups) {
  std::optional<std::size_t> best;
  std::vector<double> means;
  for (std::size_t c = 0; c < groups.size(); ++c) {
    means.push_back(groups[c].cost.empty() ? std::nan("") : stats::describe(groups[c].cost).mean);
    if (std::isfinite(means[c]) && (!best || better(e.cost_direction, means[c], means[*best]))) best = c;
  }
  if (!best || groups.size() < 2) return nullptr;
  return {{"name", e.planners[*best].label}, {"by", "mean"}, {"metric", e.cost}, {"mean", means[*best]},
          {"direction", std::string(to_string(e.cost_direction))}};
}

}  // namespace

void GroupMetrics::add(const Trial& t) {
  const core::RunRecord& r = t.record;
  cd_calls.push_back(static_cast<double>(r.cd_calls()));
  time_s.push_back(r.wall_time_s);
  nodes.push_back(static_cast<double>(r.nodes));
  cd_calls_training.push_back(static_cast<double>(r.cd_calls_training));
  cd_calls_planning.push_back(static_cast<double>(r.cd_calls_planning + r.cd_calls_query));
  const auto trained = r.extra.find("training_nodes");
  const auto planned = r.extra.find("planning_nodes");
  nodes_training.push_back(trained != r.extra.end() ? trained->second : 0.0);
  nodes_planning.push_back(planned != r.extra.end() ? planned->second : static_cast<double>(r.nodes));
  if (r.status == core::PlanStatus::kSolved) path_length.push_back(r.path_length);
  ++statuses[std::string(core::to_string(r.status))];
  const MetricSample s = metric_sample(r, cost_metric);
  if (s.kind == MetricSample::Kind::kValue) cost.push_back(s.value);
  if (s.kind == MetricSample::Kind::kMissing) ++cost_missing;
  for (const auto& [name, value] : r.extra) {
    if (std::isfinite(value)) extras[name].push_back(value);
  }
}

ExperimentMetrics empty_metrics(const Experiment& e) {
  GroupMetrics g;
  g.cost_metric = e.cost;
  return ExperimentMetrics(e.problems.size(), std::vector<GroupMetrics>(e.planners.size(), g));
}

nlohmann::json summarize(const Experiment& e, const ExperimentMetrics& metrics, double alpha) {
  nlohmann::json out;
  out["experiment"] = {{"name", e.name},
                       {"seed", e.seed},
                       {"runs", e.runs},
                       {"time_limit_s", e.time_limit_s},
                       // null: not given, each run's problem or planner default
                       {"node_limit", e.node_limit ? nlohmann::json(*e.node_limit) : nlohmann::json()},
                       {"common_seeds", e.common_seeds},
                       {"fingerprint", e.fingerprint},
                       {"censoring", "runs stopped at a limit enter cost statistics with the cost spent"}};
  if (e.cost != kDefaultCost) out["experiment"]["cost"] = e.cost;  // only when set: default outputs unchanged
  out["experiment"]["cost_direction"] = std::string(to_string(e.cost_direction));
  out["problems"] = nlohmann::json::array();
  for (std::size_t p = 0; p < e.problems.size(); ++p) {
    nlohmann::json pj = {{"name", e.problems[p].label}, {"file", e.problems[p].file.string()}};
    pj["planners"] = nlohmann::json::array();
    for (std::size_t c = 0; c < e.planners.size(); ++c) {
      const GroupMetrics& g = metrics[p][c];
      const std::size_t solved = g.statuses.count("solved") != 0 ? g.statuses.at("solved") : 0;
      nlohmann::json gj = {{"name", e.planners[c].label},
                           {"planner", e.planners[c].planner},
                           {"n", g.runs()},
                           {"solved", solved},
                           {"solved_percent", g.runs() ? 100.0 * solved / g.runs() : 0.0},
                           {"statuses", g.statuses},
                           {"cd_calls", describe_json(g.cd_calls)},
                           {"time_s", describe_json(g.time_s)},
                           {"nodes", describe_json(g.nodes)},
                           {"path_length", describe_json(g.path_length)},
                           {"by_phase",
                            {{"cd_calls_training", describe_json(g.cd_calls_training)},
                             {"cd_calls_planning", describe_json(g.cd_calls_planning)},
                             {"nodes_training", describe_json(g.nodes_training)},
                             {"nodes_planning", describe_json(g.nodes_planning)}}}};
      if (e.planners[c].kind == MethodKind::kNavigator) gj["kind"] = "navigation";  // planners: as before
      if (e.cost != kDefaultCost) {
        gj["cost"] = describe_json(g.cost);
        gj["cost"]["metric"] = e.cost;
        gj["cost"]["missing"] = g.cost_missing;
        if (solved_only_metric(e.cost)) gj["cost"]["solved_only"] = true;
      }
      if (!g.extras.empty()) {
        nlohmann::json extra = nlohmann::json::object();
        for (const auto& [name, values] : g.extras) extra[name] = describe_json(values);
        gj["metrics"] = std::move(extra);
      }
      pj["planners"].push_back(std::move(gj));
    }
    if (nlohmann::json best = best_json(e, metrics[p]); !best.is_null()) pj["best"] = std::move(best);
    if (e.planners.size() >= 2) pj["tests"] = tests_json(e, metrics[p], alpha);
    out["problems"].push_back(std::move(pj));
  }
  return out;
}

}  // namespace amp::bench
