#include "amp/core/version.hpp"
#include "amp/bench/ompl_database_writer.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <regex>

#include "amp/core/error.hpp"
#include "ompl_fixture.hpp"

namespace amp::bench {
namespace {

using test::query;

std::filesystem::path write_database(const std::filesystem::path& dir, const Experiment& e) {
  const auto db = dir / "results.db";
  OmplDatabaseWriter w(db, e, test::fixed_run_info());
  for (std::size_t i = 0; i < e.trial_count(); ++i) w.add(test::make_trial(e, i));
  w.finish();
  return db;
}

TEST(OmplDatabaseWriter, PassesOmplsCheckerWithRowCounts) {
  AMP_SKIP_WITHOUT_OMPL_DB_CHECK();
  test::TempDir dir("db_check");
  const Experiment e = test::make_experiment(dir.path);
  const auto db = write_database(dir.path, e);
  const auto out = dir.path / "check.txt";
  const int rc = test::run_ompl_db_check("--db '" + db.string() + "'", out);
  const std::string text = test::read_text(out);
  EXPECT_EQ(rc, 0) << text;
  EXPECT_NE(text.find("experiments 2\n"), std::string::npos) << text;
  EXPECT_NE(text.find("plannerConfigs 2\n"), std::string::npos) << text;
  EXPECT_NE(text.find("runs 12\n"), std::string::npos) << text;
  EXPECT_NE(text.find("progress 0\n"), std::string::npos) << text;
  EXPECT_NE(text.find("enums 10\n"), std::string::npos) << text;
  // computeViews made OMPL's views. prm_k5 solves runs 0 and 2 of both problems (4 of 6), prm_draw
  // 3 of 6 (its run 1 never solves, nor its run 2 on the corridor).
  const auto best = query(db, "SELECT plannerid, avg_solved FROM bestPlannerConfigs");
  ASSERT_EQ(best.size(), 2u);
  EXPECT_EQ(best[0].at("plannerid"), "i:1");
  EXPECT_DOUBLE_EQ(std::stod(best[0].at("avg_solved").substr(2)), 4.0 / 6.0);
  EXPECT_EQ(best[1].at("plannerid"), "i:2");
  EXPECT_DOUBLE_EQ(std::stod(best[1].at("avg_solved").substr(2)), 3.0 / 6.0);
  EXPECT_EQ(query(db, "SELECT * FROM bestPlannerConfigsPerExperiment").size(), 4u);  // configs x problems
}

TEST(OmplDatabaseWriter, RunsHoldSolvedTimeAndStatusOfEveryTrial) {
  test::TempDir dir("db_runs");
  const Experiment e = test::make_experiment(dir.path);
  const auto db = write_database(dir.path, e);
  const auto rows = query(db,
                          "SELECT experiments.name AS problem, plannerConfigs.name AS planner, runs.* FROM runs "
                          "JOIN experiments ON experiments.id = runs.experimentid "
                          "JOIN plannerConfigs ON plannerConfigs.id = runs.plannerid ORDER BY runs.id");
  ASSERT_EQ(rows.size(), 12u);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& r = rows[i];
    const std::size_t problem = i / 6, planner = (i % 6) / 3;
    const int run = static_cast<int>(i % 3);
    const core::PlanStatus status = test::expected_status(problem, planner, run);
    SCOPED_TRACE("row " + std::to_string(i));
    EXPECT_EQ(r.at("problem"), problem == 0 ? "t:corridor" : "t:maze");
    EXPECT_EQ(r.at("planner"), planner == 0 ? "t:geometric_prm_k5" : "t:geometric_prm_draw");
    EXPECT_EQ(r.at("run"), "i:" + std::to_string(run));
    EXPECT_DOUBLE_EQ(std::stod(r.at("time").substr(2)), 0.125 * static_cast<double>(i + 1));
    const bool solved = status == core::PlanStatus::kSolved;
    EXPECT_EQ(r.at("solved"), solved ? "i:1" : "i:0");
    // OMPL's StatusType values: TIMEOUT 4, EXACT_SOLUTION 6, CRASH 7, ABORT 8.
    const std::map<core::PlanStatus, std::string> ompl = {{core::PlanStatus::kSolved, "i:6"},
                                                          {core::PlanStatus::kTimeout, "i:4"},
                                                          {core::PlanStatus::kError, "i:7"},
                                                          {core::PlanStatus::kNodeLimit, "i:8"}};
    EXPECT_EQ(r.at("status"), ompl.at(status));
    EXPECT_EQ(r.at("amp_status"), "t:" + std::string(core::to_string(status)));
    EXPECT_EQ(r.count("memory"), 0u);  // not measured: NULL
    EXPECT_EQ(r.count("solution_length"), solved ? 1u : 0u);
    if (solved) {
      EXPECT_EQ(r.at("solution_segments"), "i:4");
      EXPECT_EQ(r.at("approximate_solution"), "i:0");
      EXPECT_DOUBLE_EQ(std::stod(r.at("solution_length").substr(2)), 1.5 + static_cast<double>(i));
    }
    EXPECT_EQ(r.at("graph_states"), "i:" + std::to_string(50 + i));
    EXPECT_EQ(r.at("collision_checks"), "i:" + std::to_string(111 + 2 * i));
    EXPECT_EQ(r.at("cd_calls_training"), "i:" + std::to_string(100 + i));
    EXPECT_EQ(r.at("valid_segment_fraction"), "r:0.75");
    EXPECT_EQ(r.at("seed"), i == 0 ? "t:18446744073709551615" : "t:" + std::to_string(1000 + i));
    if (planner == 0) {
      EXPECT_EQ(r.at("node_type_A"), "r:3");
      EXPECT_EQ(r.at("extra_nodes"), "r:7");
      EXPECT_EQ(r.count("param_k"), 0u);
    } else {
      EXPECT_EQ(r.at("param_k"), run % 2 == 0 ? "r:5" : "r:10");
      EXPECT_EQ(r.count("regions"), run == 2 ? 1u : 0u);
    }
    if (status == core::PlanStatus::kError) {
      EXPECT_EQ(r.at("message"), "t:bad thing, on line two");
    }
  }
}

TEST(OmplDatabaseWriter, EnumsExperimentsAndConfigs) {
  test::TempDir dir("db_tables");
  const Experiment e = test::make_experiment(dir.path);
  const auto db = write_database(dir.path, e);
  const auto enums = query(db, "SELECT * FROM enums ORDER BY value");
  ASSERT_EQ(enums.size(), 10u);
  const std::vector<std::string> names = {"Unknown status", "Invalid start", "Invalid goal", "Unrecognized goal type",
                                          "Timeout", "Approximate solution", "Exact solution", "Crash", "Abort",
                                          "Infeasible"};
  for (std::size_t i = 0; i < names.size(); ++i) {
    EXPECT_EQ(enums[i].at("name"), "t:status");
    EXPECT_EQ(enums[i].at("value"), "i:" + std::to_string(i));
    EXPECT_EQ(enums[i].at("description"), "t:" + names[i]);
  }
  const auto exps = query(db, "SELECT * FROM experiments ORDER BY id");
  ASSERT_EQ(exps.size(), 2u);
  EXPECT_EQ(exps[0].at("name"), "t:corridor");
  EXPECT_EQ(exps[0].at("runcount"), "i:3");
  EXPECT_EQ(exps[0].at("timelimit"), "r:5");
  EXPECT_EQ(exps[0].at("memorylimit"), "r:0");
  EXPECT_EQ(exps[0].at("seed"), "t:42");
  EXPECT_EQ(exps[0].at("version"), std::string("t:AMP ") + core::kVersion);
  EXPECT_EQ(exps[0].at("hostname"), "t:testhost");
  EXPECT_EQ(exps[0].at("date"), "t:2024-01-02T03:04:05Z");
  EXPECT_EQ(exps[0].at("node_limit"), "i:1000");
  EXPECT_EQ(exps[0].at("fingerprint"), "t:abc123");
  // The file's text, with the line that would end OMPL's <<<| block indented, and a final newline.
  EXPECT_EQ(exps[0].at("setup"), "t:world: corridor\nstart: [0, 0]\n |>>> not the end\ngoal: [1, 1]\n");
  EXPECT_EQ(exps[1].at("setup"), std::string("t:") + test::kMazeText);
  // totaltime: the sum of the problem's run times, 0.125 * (1 + ... + 6) and 0.125 * (7 + ... + 12).
  EXPECT_EQ(exps[0].at("totaltime"), "r:2.625");
  EXPECT_EQ(exps[1].at("totaltime"), "r:7.125");
  const auto configs = query(db, "SELECT * FROM plannerConfigs ORDER BY id");
  ASSERT_EQ(configs.size(), 2u);
  EXPECT_EQ(configs[0].at("name"), "t:geometric_prm_k5");
  EXPECT_EQ(configs[0].at("settings"), "t:amp_planner = prm\n;k = 5\n;");
  EXPECT_EQ(configs[1].at("settings"), "t:amp_planner = prm\n;k = drawn from {5, 10}\n;lazy = true\n;");
}

TEST(OmplDatabaseWriter, RefusesAnExistingFile) {
  test::TempDir dir("db_exists");
  const Experiment e = test::make_experiment(dir.path);
  const auto db = dir.path / "results.db";
  test::write_text(db, "keep me");
  EXPECT_THROW(OmplDatabaseWriter(db, e, test::fixed_run_info()), FileError);
  EXPECT_EQ(test::read_text(db), "keep me");
}

TEST(OmplDatabaseWriter, UnreadableProblemFileLeavesNoDatabase) {
  test::TempDir dir("db_missing");
  Experiment e = test::make_experiment(dir.path);
  e.problems[1].file = dir.path / "missing.yaml";
  const auto db = dir.path / "results.db";
  EXPECT_THROW(OmplDatabaseWriter(db, e, test::fixed_run_info()), FileError);
  EXPECT_FALSE(std::filesystem::exists(db));
}

TEST(OmplDatabaseWriter, ManyRunsAcrossTransactions) {
  test::TempDir dir("db_many");
  Experiment e = test::make_experiment(dir.path);
  e.problems.resize(1);
  e.planners.resize(1);
  e.runs = 2500;  // three transactions of kRowsPerTransaction rows
  const auto db = write_database(dir.path, e);
  const auto rows = query(db, "SELECT COUNT(*) AS n, SUM(solved) AS s, MAX(run) AS last FROM runs");
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].at("n"), "i:2500");
  EXPECT_EQ(rows[0].at("s"), "i:2499");  // only run 1 times out
  EXPECT_EQ(rows[0].at("last"), "i:2499");
}

// The facts the database's experiments rows record about the machine.
TEST(CurrentRunInfo, NamesHostVersionDateAndThreads) {
  const RunInfo info = current_run_info(3);
  char host[256] = {};
  ASSERT_EQ(gethostname(host, sizeof host - 1), 0);
  EXPECT_EQ(info.hostname, host);
  EXPECT_EQ(info.version, std::string("AMP ") + core::kVersion);
  EXPECT_EQ(info.threads, 3);
  EXPECT_TRUE(std::regex_match(info.date, std::regex(R"(\d{4}-\d{2}-\d{2}T\d{2}:\d{2}:\d{2}Z)"))) << info.date;
  EXPECT_NE(info.cpu_info.find("logical cores)"), std::string::npos) << info.cpu_info;
}

}  // namespace
}  // namespace amp::bench
