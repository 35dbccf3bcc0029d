#pragma once
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "amp/bench/experiment.hpp"

namespace amp::bench {

// The numbers of one problem x planner configuration that the summary needs: a few doubles per run,
// never the runs themselves.
struct GroupMetrics {
  std::vector<double> cd_calls;
  std::vector<double> time_s;
  std::vector<double> nodes;
  std::vector<double> path_length;  // solved runs only
  // The cost split by phase (UAS's Table 4): training (a learner's preparatory roadmap), and the
  // rest (planning + query); nodes likewise, from the run's training_nodes extra when it has one.
  std::vector<double> cd_calls_training, cd_calls_planning, nodes_training, nodes_planning;
  std::map<std::string, std::size_t> statuses;
  // The experiment's cost (Experiment::cost): each run's value of it, and how many runs lacked it
  // (an extra the method did not report, or reported as NaN); solved-only metrics skip unsolved runs.
  std::string cost_metric = "cd_calls";
  std::vector<double> cost;
  std::size_t cost_missing = 0;
  // Every extra metric the runs report (finite values only), by name.
  std::map<std::string, std::vector<double>> extras;

  std::size_t runs() const { return cd_calls.size(); }
  void add(const Trial& t);
};

// metrics[problem][planner] as the experiment orders them.
using ExperimentMetrics = std::vector<std::vector<GroupMetrics>>;

ExperimentMetrics empty_metrics(const Experiment& e);

// summary.json: the experiment's cost_direction ("lower" or "higher": which values of the cost are
// better); per problem x planner, n, solved %, statuses ("kind": "navigation" for a navigation
// method), and for CD calls, time, nodes and path length: mean, std, CV, median, quartiles, min, max
// and a histogram; the same for every extra metric under "metrics", and for a cost other than CD
// calls under "cost"; per problem, "best": the method with the best mean cost in that direction,
// and the tests between its planners on the experiment's cost: Brown-Forsythe, one-way ANOVA,
// Welch, Kruskal-Wallis, REGWQ (skipped, saying why, when some run lacks the cost metric). Runs that
// end at a limit enter the cost statistics with the cost they had spent (censored at the limit, as
// the run-cost paper treats them); path length uses solved runs only.
nlohmann::json summarize(const Experiment& e, const ExperimentMetrics& metrics, double alpha = 0.01);

}  // namespace amp::bench
