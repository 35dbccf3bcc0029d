// report.html: one self-contained page that names every problem and planner, has a table row per
// planner, draws SVG, says the tests in words, and never prints nan or null, even for planners
// without runs, problems with one planner, or statistics that do not exist.
#include "amp/core/version.hpp"
#include "amp/bench/report.hpp"

#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>

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

class ReportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("amp-report-test-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  Experiment walls_experiment(const std::vector<std::string>& labels) const {
    Experiment e;
    e.file = dir_ / "experiment.yaml";
    e.name = "Report <test> & friends";  // needs escaping
    e.seed = 7;
    e.runs = 4;
    e.time_limit_s = 20.0;
    e.node_limit = 20000;
    e.fingerprint = "0123abcd";
    auto problem = std::make_shared<world::Problem>(world::load_problem(fs::path(AMP_SOURCE_DIR) / "problems/walls.yaml"));
    e.problems.push_back({problem->name, problem->file, problem, {}});
    for (std::size_t i = 0; i < labels.size(); ++i) {
      e.planners.push_back({labels[i], "prm", {{"k", 10 * static_cast<int>(i + 1)}}, {}});
    }
    return e;
  }

  static RunInfo info() {
    RunInfo i;
    i.hostname = "test-host";
    i.cpu_info = "test CPU";
    i.date = "2024-01-02T03:04:05Z";
    i.version = std::string("AMP ") + core::kVersion;
    i.threads = 2;
    return i;
  }

  std::string page() const { return page_in(dir_); }
  static std::string page_in(const fs::path& dir) {
    std::ifstream in(dir / "report.html");
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }

  static std::size_t count_of(const std::string& text, const std::string& needle) {
    std::size_t n = 0;
    for (auto pos = text.find(needle); pos != std::string::npos; pos = text.find(needle, pos + 1)) ++n;
    return n;
  }

  // No network: the only URL allowed is the SVG namespace, and nothing loads from elsewhere.
  static void expect_self_contained(std::string html) {
    const std::string ns = "xmlns=\"http://www.w3.org/2000/svg\"";
    for (auto pos = html.find(ns); pos != std::string::npos; pos = html.find(ns)) html.erase(pos, ns.size());
    EXPECT_EQ(html.find("http://"), std::string::npos);
    EXPECT_EQ(html.find("https://"), std::string::npos);
    EXPECT_EQ(html.find("<script"), std::string::npos);
    EXPECT_EQ(html.find("<link"), std::string::npos);
    EXPECT_EQ(html.find(" src="), std::string::npos);
  }

  static void expect_no_missing_values(const std::string& html) {
    std::smatch m;
    EXPECT_FALSE(std::regex_search(html, m, std::regex(R"(\b(nan|NaN|NAN|null|inf)\b)")))
        << "found '" << m.str() << "' near: " << html.substr(std::max<long>(0, m.position() - 120), 240);
  }

  fs::path dir_;
};

TEST_F(ReportTest, BenchRunWritesASelfContainedReport) {
  const Experiment e = walls_experiment({"prm-k10", "prm-k20"});
  BenchOptions o;
  o.out_dir = dir_ / "out";
  o.threads = 2;
  const BenchResult r = run_experiment(e, o);
  ASSERT_EQ(r.written, 8u);
  ASSERT_TRUE(fs::is_regular_file(o.out_dir / "report.html"));
  const std::string html = page_in(o.out_dir);
  expect_self_contained(html);
  expect_no_missing_values(html);
  EXPECT_NE(html.find("Report &lt;test&gt; &amp; friends"), std::string::npos);
  EXPECT_EQ(html.find("<test>"), std::string::npos);
  EXPECT_NE(html.find(">Walls <span class=\"file\">"), std::string::npos);
  for (const std::string label : {"prm-k10", "prm-k20"}) {
    // One row of the cost table per planner, with its 4 runs.
    EXPECT_EQ(count_of(html, "<strong>" + label + "</strong></td><td>4</td>"), 1u) << label;
  }
  EXPECT_NE(html.find("0123abcd"), std::string::npos);
  EXPECT_NE(html.find("Threads</dt><dd>2</dd>"), std::string::npos);
  // The scene, the box plot and a histogram per planner.
  EXPECT_GE(count_of(html, "<svg"), 4u);
  EXPECT_NE(html.find("class=\"path\""), std::string::npos) << "the first solved run is drawn with its path";
  EXPECT_NE(html.find("Brown\u2013Forsythe test"), std::string::npos);
  EXPECT_NE(html.find("Kruskal\u2013Wallis"), std::string::npos);
  EXPECT_NE(html.find("REGWQ"), std::string::npos);
  EXPECT_NE(html.find("has the lowest coefficient of variation"), std::string::npos);
  EXPECT_EQ(html.find("Cost by phase"), std::string::npos) << "no planner trains: no phase table";
}

// A 3-D problem's rows link their first run (the first seed) in the 3-D viewer, a page written
// beside the report from a re-run of that seed; a 2-D problem gets none.
TEST_F(ReportTest, ThreeDRowsLinkTheirFirstRunInTheViewer) {
  Experiment e = walls_experiment({"prm-k10", "prm-k20"});
  // One run per row, ended by solving or by the node limit, never by the clock: a sanitizer build
  // on a busy machine runs far slower than the 20 s the other tests allow. The 3-D problem is
  // OMPL.app's cage and window, which PRM solves in a few nodes: Walls 3-D took 5.8 s here in the
  // Release build and 322 s under the sanitizers, the longest test of the suite.
  e.runs = 1;
  e.time_limit_s = 3600.0;
  auto cage = std::make_shared<world::Problem>(world::load_problem(fs::path(AMP_SOURCE_DIR) / "problems/ompl/cage_window.cfg"));
  e.problems.push_back({cage->name, cage->file, cage, {}});
  BenchOptions o;
  o.out_dir = dir_ / "out";
  o.threads = 2;
  ASSERT_EQ(run_experiment(e, o).written, 4u);
  const std::string html = page_in(o.out_dir);
  expect_self_contained(html);
  std::vector<fs::path> pages;
  for (const auto& entry : fs::directory_iterator(o.out_dir / "viewer")) pages.push_back(entry.path().filename());
  std::sort(pages.begin(), pages.end());
  ASSERT_EQ(pages, (std::vector<fs::path>{"p1-CageWindow-0-prm-k10.html", "p1-CageWindow-1-prm-k20.html"}));
  for (const fs::path& page : pages) EXPECT_EQ(count_of(html, "href=\"viewer/" + page.string() + "\""), 1u) << page;
  std::ifstream in(o.out_dir / "viewer" / pages[0]);
  std::stringstream viewer;
  viewer << in.rdbuf();
  std::uint64_t seed = 0;
  for (std::size_t i = 0; i < e.trial_count(); ++i) {
    const TrialId id = trial_id(e, i);
    if (id.problem == 1 && id.planner == 0 && id.run == 0) seed = trial_seed(e, id);
  }
  EXPECT_NE(viewer.str().find("prm-k10, run 0, seed " + std::to_string(seed)), std::string::npos);
  EXPECT_NE(viewer.str().find("certified collision-free along its whole length"), std::string::npos);
}

TEST_F(ReportTest, ALearnerGetsTheCostByPhaseTable) {
  Experiment e = walls_experiment({"prm"});
  e.runs = 3;
  e.planners.push_back({"uas", "uas", {}, {}});
  BenchOptions o;
  o.out_dir = dir_ / "out";
  o.threads = 2;
  ASSERT_EQ(run_experiment(e, o).written, 6u);
  std::ifstream in(o.out_dir / "summary.json");
  const nlohmann::json s = nlohmann::json::parse(in);
  const auto& planners = s["problems"][0]["planners"];
  const auto& prm = planners[0]["by_phase"];
  const auto& uas = planners[1]["by_phase"];
  EXPECT_EQ(prm["cd_calls_training"]["max"], 0.0);
  EXPECT_EQ(prm["nodes_planning"]["median"], planners[0]["nodes"]["median"]);
  EXPECT_GT(uas["cd_calls_training"]["min"].get<double>(), 0.0);
  EXPECT_EQ(uas["nodes_training"]["median"], 200.0);
  // Every run's phases add up to its total, so the means do too.
  EXPECT_NEAR(uas["cd_calls_training"]["mean"].get<double>() + uas["cd_calls_planning"]["mean"].get<double>(),
              planners[1]["cd_calls"]["mean"].get<double>(), 1e-6);
  const std::string html = page_in(o.out_dir);
  EXPECT_NE(html.find("Cost by phase"), std::string::npos);
  expect_no_missing_values(html);
}

// The paper's Table 1 (Hwang-Ahuja problem) and results, given as summary.json: the page says them
// as the paper does.
TEST_F(ReportTest, TestsInWordsFollowThePaper) {
  const Experiment e = walls_experiment({"PRM-C", "PRM-G", "PRM-L"});
  using Json = nlohmann::json;
  auto planner = [](const char* name, double mean, double sd, double cv) {
    return Json{{"name", name}, {"planner", "prm"}, {"n", 240}, {"solved", 240}, {"solved_percent", 100.0},
                {"statuses", {{"solved", 240}}},
                {"cd_calls", {{"n", 240}, {"mean", mean}, {"std", sd}, {"cv_percent", cv}, {"min", nullptr}}}};
  };
  auto test = [](double f, double df1, double df2, double p) {
    return Json{{"statistic", f}, {"df1", df1}, {"df2", df2}, {"p_value", p}, {"status", "ok"}};
  };
  Json problem = {{"name", "Hwang-Ahuja"},
                  {"planners", {planner("PRM-C", 2021367, 3308323, 164), planner("PRM-G", 804865, 1357438, 169),
                                planner("PRM-L", 816762, 800089, 98)}}};
  problem["tests"] = {{"levene_brown_forsythe", test(5.0, 2, 717, 0.0071)},
                      {"anova", test(23.4, 2, 717, 1.2e-10)},
                      {"welch_anova", test(14.2, 2, 451.29, 1.0e-6)},
                      {"kruskal_wallis", {{"statistic", 1.3}, {"df1", 2}, {"df2", nullptr}, {"p_value", 0.52},
                                          {"status", "ok"}}},
                      {"regwq",
                       {{"alpha", 0.01}, {"status", "ok"}, {"subsets", {{"PRM-G", "PRM-L"}, {"PRM-C"}}},
                        {"pairs", {{{"a", "PRM-C"}, {"b", "PRM-G"}, {"differs", true}},
                                   {{"a", "PRM-C"}, {"b", "PRM-L"}, {"differs", true}},
                                   {{"a", "PRM-G"}, {"b", "PRM-L"}, {"differs", false}}}}}}};
  write_report(e, Json{{"problems", {problem}}}, info(), dir_);
  const std::string html = page();
  expect_no_missing_values(html);
  expect_self_contained(html);
  EXPECT_NE(html.find("the variances of run cost differ significantly (F(2, 717) = 5.00, p = 0.0071)"),
            std::string::npos);
  EXPECT_NE(html.find("the mean run costs differ significantly (F(2, 717) = 23.4, p &lt; 0.0001)"), std::string::npos)
      << "(the p-value text is escaped)";
  EXPECT_NE(html.find("(F(2, 451.3) = 14.2, p &lt; 0.0001)"), std::string::npos);
  EXPECT_NE(html.find("do not differ significantly in location (H = 1.30, df = 2, p = 0.52)"), std::string::npos);
  EXPECT_NE(html.find("homogeneous subsets {<strong>PRM-G</strong>, <strong>PRM-L</strong>} and "
                      "{<strong>PRM-C</strong>}: <strong>PRM-C</strong>\u2019s mean run cost differs from "
                      "<strong>PRM-G</strong>\u2019s and <strong>PRM-L</strong>\u2019s."),
            std::string::npos);
  EXPECT_NE(html.find("<strong>PRM-L</strong> has the lowest coefficient of variation (98\u00a0%)"),
            std::string::npos);
  EXPECT_NE(html.find("<strong>PRM-G</strong> has the lowest mean run cost (804,865 CD calls)"), std::string::npos);
  EXPECT_NE(html.find("2,021,367"), std::string::npos);  // Table 1's mean, grouped as the paper prints it
  EXPECT_NE(html.find("no runs.csv beside this report"), std::string::npos);  // nothing to redraw or chart
  EXPECT_NE(html.find("No runs to chart."), std::string::npos);
}

// Planners with zero or one run, zero variance, and an experiment with one planner: no tests, no
// nan. The runs are written to runs.csv by hand, as write_outputs would find them.
TEST_F(ReportTest, DegenerateGroupsRenderSensibly) {
  Experiment e = walls_experiment({"none", "single", "three"});
  auto write_runs = [&](const std::vector<std::pair<std::size_t, core::PlanStatus>>& trials) {
    RunsCsvWriter csv(dir_ / "runs.csv", e, false);
    ExperimentMetrics m = empty_metrics(e);
    for (const auto& [index, status] : trials) {
      Trial t;
      t.id = trial_id(e, index);
      t.seed = trial_seed(e, t.id);
      t.record.cd_calls_planning = status == core::PlanStatus::kSolved ? 100 : 500;  // zero variance when solved
      t.record.status = status;
      t.record.path_length = status == core::PlanStatus::kSolved ? 100.0 : 0.0;
      csv.add(t);
      m[t.id.problem][t.id.planner].add(t);
    }
    csv.finish();
    return summarize(e, m);
  };
  // Trial index = planner * runs + run: "none" has no runs, "single" one timeout, "three" three solved.
  const auto solved = core::PlanStatus::kSolved;
  write_report(e, write_runs({{4, core::PlanStatus::kTimeout}, {8, solved}, {9, solved}, {10, solved}}), info(), dir_);
  std::string html = page();
  expect_no_missing_values(html);
  EXPECT_NE(html.find("Tests between planners skipped"), std::string::npos);
  EXPECT_NE(html.find("<strong>none</strong> has no runs"), std::string::npos);
  EXPECT_NE(html.find("<strong>single</strong> 1 of 1 (1 timeout)"), std::string::npos);
  EXPECT_NE(html.find(">no runs</text>"), std::string::npos);  // in the box plot
  EXPECT_NE(html.find("none (no runs)"), std::string::npos);   // its histogram
  EXPECT_NE(html.find("Solution of <strong>three</strong>, run 0"), std::string::npos);  // trial 8, re-run
  EXPECT_EQ(count_of(html, "<svg"), 5u);  // scene, box plot, three histograms

  e.planners.resize(1);
  html.clear();
  write_report(e, write_runs({{0, solved}, {1, solved}}), info(), dir_);
  html = page();
  expect_no_missing_values(html);
  EXPECT_NE(html.find("One planner only: no tests between planners."), std::string::npos);
  EXPECT_NE(html.find("<strong>none</strong> has a coefficient of variation of 0\u00a0%."), std::string::npos);
}

}  // namespace
}  // namespace amp::bench
