// summary.json and report.html rank methods in the cost's direction: on a share solved the highest
// mean is the best, on a cost the lowest, as before. The runs are written to runs.csv by hand (as
// write_outputs would find them), so which method is best is known here; a real SINS experiment
// then checks that a navigation row says its runs are sequences of worlds and draws no path.
#include "amp/bench/report.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "amp/bench/bench_runner.hpp"
#include "amp/bench/runs_csv.hpp"
#include "amp/bench/summary.hpp"
#include "amp/world/problem.hpp"
#include "support/source_tree.hpp"

namespace amp::bench {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

class ReportDirection : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("amp-report-direction-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Two PRM configurations, "few" and "many", on walls.yaml, 4 runs each, ranked on `cost`.
  Experiment experiment(const std::string& cost, CostDirection direction) const {
    Experiment e;
    e.file = dir_ / "experiment.yaml";
    e.name = "direction";
    e.runs = 4;
    e.time_limit_s = 20.0;
    e.node_limit = 20000;
    e.cost = cost;
    e.cost_direction = direction;
    const fs::path walls = fs::path(AMP_SOURCE_DIR) / "problems" / "walls.yaml";
    auto problem = std::make_shared<world::Problem>(world::load_problem(walls));
    e.problems.push_back({problem->name, problem->file, problem, {}});
    e.planners.push_back({"few", "prm", {{"k", 10}}, {}});
    e.planners.push_back({"many", "prm", {{"k", 20}}, {}});
    return e;
  }

  // Runs of "few" score {0, 0.05, 0.05, 0.1} on `extra` (mean 0.05), runs of "many" {0.8, 0.9, 0.9, 1}
  // (mean 0.9); written to runs.csv and summarized.
  Json write_runs(const Experiment& e, const std::string& extra) const {
    const double values[2][4] = {{0.0, 0.05, 0.05, 0.1}, {0.8, 0.9, 0.9, 1.0}};
    RunsCsvWriter csv(dir_ / "runs.csv", e, false);
    ExperimentMetrics m = empty_metrics(e);
    for (std::size_t index = 0; index < e.trial_count(); ++index) {
      Trial t;
      t.id = trial_id(e, index);
      t.seed = trial_seed(e, t.id);
      t.record.status = core::PlanStatus::kSolved;
      t.record.cd_calls_planning = 100 + index;
      t.record.path_length = 10.0;
      t.record.extra[extra] = values[t.id.planner][t.id.run];
      csv.add(t);
      m[t.id.problem][t.id.planner].add(t);
    }
    csv.finish();
    return summarize(e, m);
  }

  std::string report(const Experiment& e, const Json& summary) const {
    RunInfo info;
    info.version = "AMP test";
    write_report(e, summary, info, dir_);
    std::stringstream ss;
    ss << std::ifstream(dir_ / "report.html").rdbuf();
    return ss.str();
  }

  // The cost table's row of `name`: from its name cell to the end of the row.
  static std::string row_of(const std::string& html, const std::string& name) {
    const auto begin = html.find("<strong>" + name + "</strong></td><td>4</td>");
    if (begin == std::string::npos) return {};
    return html.substr(begin, html.find("</tr>", begin) - begin);
  }

  fs::path dir_;
};

TEST_F(ReportDirection, ASolvedShareRanksTheHighestMeanBest) {
  const Experiment e = experiment("solved_fraction", default_cost_direction("solved_fraction"));
  const Json s = write_runs(e, "solved_fraction");
  EXPECT_EQ(s["experiment"]["cost_direction"], "higher");
  const Json& p = s["problems"][0];
  EXPECT_EQ(p["best"]["name"], "many");
  EXPECT_DOUBLE_EQ(p["best"]["mean"].get<double>(), 0.9);
  EXPECT_EQ(p["best"]["direction"], "higher");
  EXPECT_EQ(p["tests"]["direction"], "higher");

  const std::string html = report(e, s);
  EXPECT_NE(html.find("<strong>many</strong> has the highest mean solved_fraction (0.9)"), std::string::npos);
  EXPECT_EQ(html.find("has the lowest mean"), std::string::npos);
  EXPECT_NE(row_of(html, "many").find("<span class=\"best\">0.9</span>"), std::string::npos) << row_of(html, "many");
  EXPECT_EQ(row_of(html, "few").find("<span class=\"best\">0.05</span>"), std::string::npos) << row_of(html, "few");
  EXPECT_NE(html.find("the highest mean and the lowest CV of each problem are marked"), std::string::npos);
  EXPECT_NE(html.find("<h3>solved_fraction (higher is better)</h3>"), std::string::npos);
  EXPECT_NE(html.find("solved_fraction per method (higher is better)"), std::string::npos);  // the box plot
  EXPECT_NE(html.find("the means of solved_fraction differ significantly"), std::string::npos);
  EXPECT_NE(html.find("mean solved_fraction differs from"), std::string::npos);
  EXPECT_EQ(html.find("mean run cost"), std::string::npos);
}

TEST_F(ReportDirection, ACostStillRanksTheLowestMeanBest) {
  const Experiment e = experiment("replans", default_cost_direction("replans"));
  const Json s = write_runs(e, "replans");
  EXPECT_EQ(s["experiment"]["cost_direction"], "lower");
  EXPECT_EQ(s["problems"][0]["best"]["name"], "few");
  const std::string html = report(e, s);
  EXPECT_NE(html.find("<strong>few</strong> has the lowest mean run cost (0.05 replans)"), std::string::npos);
  EXPECT_EQ(html.find("has the highest mean"), std::string::npos);
  EXPECT_NE(row_of(html, "few").find("<span class=\"best\">0.05</span>"), std::string::npos) << row_of(html, "few");
  EXPECT_NE(html.find("the lowest mean and the lowest CV of each problem are marked"), std::string::npos);
  EXPECT_NE(html.find("Run cost per planner"), std::string::npos);
  EXPECT_NE(html.find("the mean run costs differ significantly"), std::string::npos);
  EXPECT_NE(html.find("mean run cost differs from"), std::string::npos);
}

TEST_F(ReportDirection, TheExperimentsDirectionOverridesTheName) {
  const Experiment e = experiment("solved_fraction", CostDirection::kLower);
  const Json s = write_runs(e, "solved_fraction");
  EXPECT_EQ(s["problems"][0]["best"]["name"], "few");
  EXPECT_NE(report(e, s).find("<strong>few</strong> has the lowest mean run cost"), std::string::npos);
}

// SINS's three systems through the runner: each row's run is a sequence of worlds, so the page says
// so, counts complete sequences, draws no planner's path, and ranks by the highest solved_fraction.
TEST(ReportNavigationRows, ASequenceOfWorldsIsNotDrawnAsAPath) {
  const fs::path root = fs::temp_directory_path() / ("amp-report-sins-" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root);
  const std::string small = "params: {worlds: 3, step_limit: 200}}";
  std::ofstream(root / "exp.yaml") << "name: sins-tiny\nseed: 5\nruns: 2\ntime_limit: 600\ncommon_seeds: true\n"
                                   << "cost: solved_fraction\nproblems: ["
                                   << (fs::path(AMP_SOURCE_DIR) / "problems" / "sins-arena.yaml").string()
                                   << "]\nplanners:\n  - {name: static, planner: static, " << small
                                   << "\n  - {name: sins, planner: sins, " << small << "\n";
  const Experiment e = load_experiment(root / "exp.yaml");
  BenchOptions o;
  o.out_dir = root / "out";
  o.threads = 2;
  ASSERT_EQ(run_experiment(e, o).written, 4u);

  const Json s = Json::parse(std::ifstream(o.out_dir / "summary.json"));
  const Json& p = s["problems"][0];
  double best = -1.0;
  std::string best_name;
  for (const Json& c : p["planners"]) {
    EXPECT_EQ(c["kind"], "navigation");
    if (c["cost"]["mean"].get<double>() > best) best = c["cost"]["mean"].get<double>(), best_name = c["name"];
  }
  EXPECT_EQ(p["best"]["name"], best_name);

  std::stringstream ss;
  ss << std::ifstream(o.out_dir / "report.html").rdbuf();
  const std::string html = ss.str();
  EXPECT_EQ(html.find("did not reproduce"), std::string::npos);
  EXPECT_EQ(html.find("class=\"path\""), std::string::npos) << "no path is drawn for a sequence of worlds";
  EXPECT_NE(html.find("<strong>static</strong> and <strong>sins</strong> run sequences of worlds"), std::string::npos);
  EXPECT_NE(html.find("\u00a0% complete</small>"), std::string::npos);  // the overview
  EXPECT_EQ(html.find("\u00a0% solved</small>"), std::string::npos);
  EXPECT_NE(html.find("<strong>" + best_name + "</strong> has the highest mean solved_fraction"), std::string::npos);
  fs::remove_all(root);
}

}  // namespace
}  // namespace amp::bench
