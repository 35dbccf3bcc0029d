#include "amp/core/version.hpp"
#include "amp/bench/ompl_log_writer.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "amp/bench/ompl_database_writer.hpp"
#include "amp/core/error.hpp"
#include "ompl_fixture.hpp"

namespace amp::bench {
namespace {

using test::query;

std::vector<std::filesystem::path> write_logs(const std::filesystem::path& target, const Experiment& e) {
  OmplLogWriter w(target, e, test::fixed_run_info());
  for (std::size_t i = 0; i < e.trial_count(); ++i) w.add(test::make_trial(e, i));
  w.finish();
  return w.files();
}

std::string quoted_list(const std::vector<std::filesystem::path>& files) {
  std::string s;
  for (const auto& f : files) s += " '" + f.string() + "'";
  return s;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

TEST(OmplLogWriter, OneLogPerProblemInOmplsFormat) {
  test::TempDir dir("log_format");
  const Experiment e = test::make_experiment(dir.path);
  const auto files = write_logs(dir.path / "logs", e);
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files[0], dir.path / "logs" / "corridor.log");
  EXPECT_EQ(files[1], dir.path / "logs" / "maze.log");
  const auto l = lines(test::read_text(files[0]));
  ASSERT_GT(l.size(), 30u);
  EXPECT_EQ(l[0], std::string("AMP version ") + core::kVersion);
  EXPECT_EQ(l[1], "Experiment corridor");
  EXPECT_EQ(l[2], "6 experiment properties");
  EXPECT_EQ(l[9], "Running on testhost");
  EXPECT_EQ(l[10], "Starting at 2024-01-02T03:04:05Z");
  EXPECT_EQ(l[11], "<<<|");
  EXPECT_EQ(l[12], "world: corridor");
  EXPECT_EQ(l[14], " |>>> not the end");
  EXPECT_EQ(l[16], "|>>>");
  EXPECT_EQ(l[18], "Test CPU @ 1 GHz (2 logical cores)");
  EXPECT_EQ(l[20], "42 is the random seed");
  EXPECT_EQ(l[21], "5 seconds per run");
  EXPECT_EQ(l[22], "0 MB per run");
  EXPECT_EQ(l[23], "3 runs per planner");
  EXPECT_EQ(l[24], "2.625 seconds spent to collect the data");
  EXPECT_EQ(l[25], "1 enum type");
  EXPECT_EQ(l[26], "status|Unknown status|Invalid start|Invalid goal|Unrecognized goal type|Timeout|"
                   "Approximate solution|Exact solution|Crash|Abort|Infeasible");
  EXPECT_EQ(l[27], "2 planners");
  EXPECT_EQ(l[28], "geometric_prm_k5");
  EXPECT_EQ(l[29], "2 common properties");
  EXPECT_EQ(l[30], "amp_planner = prm");
  EXPECT_EQ(l[31], "k = 5");
  // Sorted property keys as OMPL writes them, then one row per run ending in "; ".
  const auto props = std::find(l.begin(), l.end(), "27 properties for each run");
  ASSERT_NE(props, l.end());
  EXPECT_EQ(*(props + 1), "amp_status TEXT");
  EXPECT_EQ(*(props + 28), "3 runs");
  EXPECT_EQ(*(props + 29), "solved; 0; 10; 1; 100; 0; 111; 2; 70; 7; 70; 50; 8; 6; ; 3; 50; 5; 0; "
                           "18446744073709551615; 0.25; 1.5; 4; 1; 6; 0.125; 0.75; ");
  EXPECT_EQ(std::count(l.begin(), l.end(), "."), 2);
  EXPECT_FALSE(std::filesystem::exists(files[0].string() + ".runs.tmp"));
  EXPECT_FALSE(std::filesystem::exists(files[0].string() + ".body.tmp"));
}

TEST(OmplLogWriter, PassesOmplsParserAndGivesTheWritersDatabase) {
  AMP_SKIP_WITHOUT_OMPL_DB_CHECK();
  test::TempDir dir("log_roundtrip");
  const Experiment e = test::make_experiment(dir.path);
  const auto files = write_logs(dir.path, e);
  const auto from_log = dir.path / "from_log.db";
  const auto out = dir.path / "check.txt";
  const int rc = test::run_ompl_db_check("--log" + quoted_list(files) + " --db '" + from_log.string() + "'", out);
  const std::string text = test::read_text(out);
  ASSERT_EQ(rc, 0) << text;
  EXPECT_NE(text.find("experiments 2\nplannerConfigs 2\nruns 12\nprogress 0\nenums 10\n"), std::string::npos) << text;

  const auto direct = dir.path / "direct.db";
  {
    OmplDatabaseWriter w(direct, e, test::fixed_run_info());
    for (std::size_t i = 0; i < e.trial_count(); ++i) w.add(test::make_trial(e, i));
    w.finish();
  }
  // Same rows, same typed values, whichever way the database was made (ids and column order aside).
  const std::string runs =
      "SELECT experiments.name AS e, plannerConfigs.name AS p, runs.* FROM runs "
      "JOIN experiments ON experiments.id = runs.experimentid JOIN plannerConfigs ON plannerConfigs.id = runs.plannerid "
      "ORDER BY e, p, runs.run";
  auto a = query(from_log, runs), b = query(direct, runs);
  ASSERT_EQ(a.size(), 12u);
  for (auto* rows : {&a, &b}) {
    for (auto& r : *rows) r.erase("id");
  }
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i], b[i]) << "row " << i;
  for (const char* sql : {"SELECT * FROM experiments ORDER BY id", "SELECT * FROM plannerConfigs ORDER BY id",
                          "SELECT * FROM enums ORDER BY value"}) {
    EXPECT_EQ(query(from_log, sql), query(direct, sql)) << sql;
  }
}

TEST(OmplLogWriter, MissingTrialsGiveEmptySectionsAndLogs) {
  AMP_SKIP_WITHOUT_OMPL_DB_CHECK();
  test::TempDir dir("log_missing");
  const Experiment e = test::make_experiment(dir.path);
  std::vector<std::filesystem::path> files;
  {
    OmplLogWriter w(dir.path, e, test::fixed_run_info());
    for (std::size_t i = 3; i < 6; ++i) w.add(test::make_trial(e, i));  // problem 0, planner 1 only
    w.finish();
    files = w.files();
  }
  const auto out = dir.path / "check.txt";
  const auto db = dir.path / "from_log.db";
  const int rc = test::run_ompl_db_check("--log" + quoted_list(files) + " --db '" + db.string() + "'", out);
  ASSERT_EQ(rc, 0) << test::read_text(out);
  EXPECT_EQ(query(db, "SELECT COUNT(*) AS n FROM runs")[0].at("n"), "i:3");
  EXPECT_EQ(query(db, "SELECT COUNT(*) AS n FROM experiments")[0].at("n"), "i:2");
  const auto l = lines(test::read_text(files[0]));
  EXPECT_NE(std::find(l.begin(), l.end(), "0 properties for each run"), l.end());
}

TEST(OmplLogWriter, SingleFileForOneProblem) {
  test::TempDir dir("log_single");
  Experiment e = test::make_experiment(dir.path);
  e.problems.resize(1);
  const auto files = write_logs(dir.path / "run.log", e);
  ASSERT_EQ(files.size(), 1u);
  EXPECT_EQ(files[0], dir.path / "run.log");
  EXPECT_TRUE(std::filesystem::exists(files[0]));
  e.problems = test::make_experiment(dir.path).problems;
  const auto two = OmplLogWriter::log_paths(dir.path / "run.log", e);
  EXPECT_EQ(two.at(1), dir.path / "run_maze.log");
}

TEST(OmplLogWriter, RefusesExistingLogsAndTrialsOutOfOrder) {
  test::TempDir dir("log_errors");
  const Experiment e = test::make_experiment(dir.path);
  test::write_text(dir.path / "maze.log", "old");
  EXPECT_THROW(OmplLogWriter(dir.path, e, test::fixed_run_info()), FileError);
  std::filesystem::remove(dir.path / "maze.log");
  OmplLogWriter w(dir.path, e, test::fixed_run_info());
  w.add(test::make_trial(e, 4));                          // problem 0, planner 1
  EXPECT_THROW(w.add(test::make_trial(e, 1)), Error);     // problem 0, planner 0: earlier
  w.add(test::make_trial(e, 7));                          // problem 1
  EXPECT_THROW(w.add(test::make_trial(e, 5)), Error);     // back to problem 0
}

}  // namespace
}  // namespace amp::bench
