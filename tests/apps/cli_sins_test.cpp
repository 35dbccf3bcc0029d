// `amp sins` end to end on short sequences: the record's keys and consistency, the same seed giving
// the same record, the files of -o DIR (and no overwriting without --force), every system meeting
// the same worlds, and the command's worlds being exactly nav::run_sequence's.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "amp/learn/case_library.hpp"
#include "amp/nav/sins/parameter_policy.hpp"
#include "amp/nav/sins/sins_plus_parameters.hpp"
#include "amp/nav/sins/sins_run.hpp"
#include "support/cli_errors_fixture.hpp"

namespace {

namespace fs = std::filesystem;
using namespace amp::test;  // CliErrors, run helpers
using ::testing::HasSubstr;

// Short: four worlds of at most 200 steps each take a few milliseconds.
const std::string kQuick = "sins --worlds 4 --step-limit 200 --seed 3";

const char* const kKeys[] = {"system",
                             "worlds",
                             "solved_fraction",
                             "steps_mean",
                             "distance_mean",
                             "distance_ratio_mean",
                             "virtual_collisions_mean",
                             "time_per_world_ms_mean",
                             "cases",
                             "seed",
                             "clutter",
                             "rejected_worlds"};
const char* const kOutcomeKeys[] = {"index",  "solved",        "steps",   "distance", "optimal", "virtual_collisions",
                                    "blocked", "min_clearance", "time_ms", "clutter"};

// The record without its wall-clock time (the one part a seed does not fix).
nlohmann::json untimed(nlohmann::json j) {
  j.erase("time_per_world_ms_mean");
  return j;
}

TEST_F(CliErrors, SinsRecordKeysAndSameSeed) {
  const RunResult r = run(kQuick + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");  // no progress bar when stderr is not a terminal
  const nlohmann::json j = nlohmann::json::parse(r.out);
  for (const char* key : kKeys) EXPECT_TRUE(j.contains(key)) << key;
  for (const auto& [key, value] : j.items()) EXPECT_FALSE(value.is_object() || value.is_array()) << key << " is not flat";
  EXPECT_EQ(j.at("system"), "adaptive");
  EXPECT_EQ(j.at("worlds"), 4);
  EXPECT_EQ(j.at("seed"), 3);
  EXPECT_DOUBLE_EQ(j.at("clutter").get<double>(), 0.25);
  const double solved = j.at("solved_fraction").get<double>();
  EXPECT_GE(solved, 0.0);
  EXPECT_LE(solved, 1.0);
  EXPECT_GT(j.at("steps_mean").get<double>(), 0.0);
  EXPECT_LE(j.at("steps_mean").get<double>(), 200.0);
  EXPECT_GT(j.at("distance_mean").get<double>(), 0.0);
  EXPECT_GE(j.at("distance_ratio_mean").get<double>(), 0.0);
  EXPECT_EQ(j.at("distance_ratio_mean").get<double>() > 0.0, solved > 0.0);  // over the solved worlds only
  EXPECT_GE(j.at("virtual_collisions_mean").get<double>(), 0.0);
  EXPECT_GE(j.at("time_per_world_ms_mean").get<double>(), 0.0);
  EXPECT_GE(j.at("cases").get<int>(), 0);
  EXPECT_LE(j.at("cases").get<int>(), 10);  // max-cases
  EXPECT_GE(j.at("rejected_worlds").get<int>(), 0);

  const nlohmann::json again = nlohmann::json::parse(run(kQuick + " --json").out);
  EXPECT_EQ(untimed(again), untimed(j));
  const nlohmann::json other = nlohmann::json::parse(run("sins --worlds 4 --step-limit 200 --seed 4 --json").out);
  EXPECT_NE(untimed(other), untimed(j));
}

TEST_F(CliErrors, SinsStaticAndRandomKeepNoCases) {
  for (const char* system : {"static", "random"}) {
    const RunResult r = run(kQuick + " --json --system " + system);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j.at("system"), system);
    EXPECT_EQ(j.at("cases"), 0);
  }
  const RunResult one = run(kQuick + " --json --max-cases 1");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  EXPECT_LE(nlohmann::json::parse(one.out).at("cases").get<int>(), 1);
}

TEST_F(CliErrors, SinsOutputFilesAndNoOverwriteWithoutForce) {
  const RunResult r = run(kQuick + " --json --param obstacle_gain=1.5 -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  for (const char* f : {"record.json", "learning.svg", "run.svg"}) EXPECT_TRUE(fs::is_regular_file(dir_ / "out" / f)) << f;

  const nlohmann::json record = nlohmann::json::parse(read_file(dir_ / "out" / "record.json"));
  nlohmann::json flat = record;  // record.json: the printed record plus the details
  for (const char* k : {"settings", "systems", "world_outcomes"}) flat.erase(k);
  EXPECT_EQ(flat, j);
  EXPECT_DOUBLE_EQ(record.at("settings").at("obstacle_gain").get<double>(), 1.5);
  EXPECT_EQ(record.at("settings").at("step_limit"), 200);
  ASSERT_EQ(record.at("world_outcomes").size(), 4u);
  int solved = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    const auto& w = record.at("world_outcomes")[i];
    for (const char* key : kOutcomeKeys) EXPECT_TRUE(w.contains(key)) << key;
    EXPECT_EQ(w.at("index"), i);
    EXPECT_GE(w.at("min_clearance").get<double>(), 0.0);
    solved += w.at("solved").get<bool>() ? 1 : 0;
  }
  EXPECT_DOUBLE_EQ(j.at("solved_fraction").get<double>(), solved / 4.0);
  // Figure 5 runs all three systems on the same worlds; the chosen one is the printed record.
  ASSERT_EQ(record.at("systems").size(), 3u);
  for (const char* s : {"static", "random", "adaptive"}) EXPECT_EQ(record.at("systems").at(s).at("worlds"), 4) << s;
  EXPECT_EQ(record.at("systems").at("adaptive").at("solved_fraction"), j.at("solved_fraction"));
  EXPECT_EQ(record.at("systems").at("adaptive").at("cases"), j.at("cases"));

  const std::string learning = read_file(dir_ / "out" / "learning.svg");
  std::size_t panels = 0;
  for (auto at = learning.find("class=\"estimator-panel\""); at != std::string::npos;
       at = learning.find("class=\"estimator-panel\"", at + 1)) {
    ++panels;
  }
  EXPECT_EQ(panels, 6u);
  for (const char* s : {">static<", ">random<", ">adaptive<", "world", "time per world (ms)"}) {
    EXPECT_THAT(learning, HasSubstr(s));
  }
  const std::string drive = read_file(dir_ / "out" / "run.svg");
  for (const char* s : {"class=\"parameter-strip\"", "class=\"driven-path\"", "class=\"obstacles\"", "world 4 of 4",
                        "obstacle gain", "noise persistence"}) {
    EXPECT_THAT(drive, HasSubstr(s));
  }

  // Again into the same directory: refused, the files untouched; with --force, written.
  { std::ofstream(dir_ / "out" / "run.svg") << "keep"; }
  const RunResult refused = run(kQuick + " -o out");
  EXPECT_EQ(refused.exit_code, kExitError);
  ASSERT_EQ(lines_of(refused.err).size(), 1u) << refused.err;
  EXPECT_THAT(refused.err, HasSubstr("-o"));
  EXPECT_THAT(refused.err, HasSubstr("--force"));
  EXPECT_EQ(refused.out, "");
  EXPECT_EQ(read_file(dir_ / "out" / "run.svg"), "keep");
  const RunResult forced = run(kQuick + " -o out --force");
  ASSERT_EQ(forced.exit_code, 0) << forced.err;
  EXPECT_NE(read_file(dir_ / "out" / "run.svg"), "keep");
  EXPECT_THAT(forced.out, HasSubstr("solved_fraction"));  // the human summary
  EXPECT_THAT(forced.out, HasSubstr("adaptive"));
  EXPECT_THAT(forced.out, HasSubstr("written to out/"));
}

// Every system meets the same worlds (the seed fixes them), whichever is chosen.
TEST_F(CliErrors, SinsSystemsMeetTheSameWorlds) {
  ASSERT_EQ(run(kQuick + " --system static -o a").exit_code, 0);
  ASSERT_EQ(run(kQuick + " --system random -o b").exit_code, 0);
  const nlohmann::json a = nlohmann::json::parse(read_file(dir_ / "a" / "record.json"));
  const nlohmann::json b = nlohmann::json::parse(read_file(dir_ / "b" / "record.json"));
  ASSERT_EQ(a.at("world_outcomes").size(), b.at("world_outcomes").size());
  for (std::size_t i = 0; i < a.at("world_outcomes").size(); ++i) {
    EXPECT_EQ(a.at("world_outcomes")[i].at("optimal"), b.at("world_outcomes")[i].at("optimal"));
    EXPECT_EQ(a.at("world_outcomes")[i].at("clutter"), b.at("world_outcomes")[i].at("clutter"));
  }
  // The static system's row in b's comparison is a's own record.
  EXPECT_EQ(b.at("systems").at("static").at("steps_mean"), a.at("steps_mean"));
  EXPECT_EQ(b.at("systems").at("static").at("solved_fraction"), a.at("solved_fraction"));
}

// The command drives exactly nav::run_sequence's worlds (same world draws, same robot stream),
// also across a change of clutter, with every setting passed on (stall_exploration included).
TEST_F(CliErrors, SinsMatchesRunSequence) {
  const RunResult r = run(kQuick +
                          " --param change_at=2 --param clutter_after=0.35 --param noise_gain=0.8 "
                          "--param stall_exploration=0.7 -o out");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json record = nlohmann::json::parse(read_file(dir_ / "out" / "record.json"));

  amp::nav::SinsSettings settings;
  settings.worlds = 4;
  settings.step_limit = 200;
  settings.change_at = 2;
  settings.clutter_after = 0.35;
  settings.stall_exploration = 0.7;
  amp::nav::SchemaParameters initial = amp::nav::SchemaParameters::middle();
  initial.noise_gain = 0.8;
  const auto policy = amp::nav::make_parameter_policy("adaptive", amp::learn::CaseSettings{}, initial, 0.7);
  const amp::nav::SequenceOutcome expected = amp::nav::run_sequence(*policy, settings, 3);
  ASSERT_EQ(record.at("world_outcomes").size(), expected.worlds.size());
  for (std::size_t i = 0; i < expected.worlds.size(); ++i) {
    const auto& got = record.at("world_outcomes")[i];
    EXPECT_EQ(got.at("solved").get<bool>(), expected.worlds[i].solved) << i;
    EXPECT_EQ(got.at("steps").get<int>(), expected.worlds[i].steps) << i;
    EXPECT_DOUBLE_EQ(got.at("distance").get<double>(), expected.worlds[i].distance) << i;
    EXPECT_DOUBLE_EQ(got.at("clutter").get<double>(), expected.worlds[i].clutter) << i;
  }
  EXPECT_GE(record.at("world_outcomes")[2].at("clutter").get<double>(), 0.35);  // the change
  EXPECT_EQ(record.at("cases"), expected.cases);
  EXPECT_EQ(record.at("rejected_worlds"), expected.rejected_worlds);
}

// --system sins-plus runs SplittingCaseParameters with the --param settings it is given (max_cases
// shared with the adaptive system's), on run_sequence's worlds, and records those settings.
TEST_F(CliErrors, SinsPlusMatchesRunSequence) {
  const RunResult r = run(kQuick + " --system sins-plus --param horizon=3 --param exploration=0.3 --max-cases 2 -o plus");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json record = nlohmann::json::parse(read_file(dir_ / "plus" / "record.json"));
  amp::nav::SinsSettings settings;
  settings.worlds = 4;
  settings.step_limit = 200;
  amp::learn::SplittingCaseSettings plus;
  plus.horizon = 3;
  plus.exploration = 0.3;
  plus.max_cases = 2;
  amp::nav::SplittingCaseParameters policy(plus);
  const amp::nav::SequenceOutcome expected = amp::nav::run_sequence(policy, settings, 3);
  ASSERT_EQ(record.at("world_outcomes").size(), expected.worlds.size());
  for (std::size_t i = 0; i < expected.worlds.size(); ++i) {
    EXPECT_EQ(record.at("world_outcomes")[i].at("steps").get<int>(), expected.worlds[i].steps) << i;
    EXPECT_DOUBLE_EQ(record.at("world_outcomes")[i].at("distance").get<double>(), expected.worlds[i].distance) << i;
  }
  EXPECT_EQ(record.at("system"), "sins-plus");
  EXPECT_EQ(record.at("settings").at("horizon"), 3);
  EXPECT_EQ(record.at("settings").at("max_cases"), 2);
  EXPECT_TRUE(record.at("systems").contains("sins-plus"));
  EXPECT_TRUE(record.at("systems").contains("adaptive"));  // -o runs the paper's three beside it

  const RunResult bad = run(kQuick + " --system sins-plus --param horizon=0");
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.err.find("horizon"), std::string::npos) << bad.err;
  EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
}

// --scale classic is the 40 m arena's world and 1000 steps: the same worlds as run_sequence at
// set_scale(kClassicScale); the default is the calibrated scale; a given --step-limit still wins.
TEST_F(CliErrors, SinsScaleChoosesTheWorldAndStepLimit) {
  const RunResult r = run("sins --worlds 3 --seed 5 --scale classic --system static -o classic");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json record = nlohmann::json::parse(read_file(dir_ / "classic" / "record.json"));
  amp::nav::SinsSettings settings;
  settings.set_scale(amp::nav::kClassicScale);
  settings.worlds = 3;
  EXPECT_DOUBLE_EQ(settings.world.width, 40.0);
  EXPECT_EQ(settings.step_limit, 1000);
  const auto policy = amp::nav::make_parameter_policy("static", amp::learn::CaseSettings{},
                                                      amp::nav::SchemaParameters::middle(), settings.stall_exploration);
  const amp::nav::SequenceOutcome expected = amp::nav::run_sequence(*policy, settings, 5);
  ASSERT_EQ(record.at("world_outcomes").size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(record.at("world_outcomes")[i].at("steps").get<int>(), expected.worlds[i].steps) << i;
    EXPECT_DOUBLE_EQ(record.at("world_outcomes")[i].at("optimal").get<double>(), expected.worlds[i].optimal) << i;
  }
  EXPECT_EQ(record.at("settings").at("step_limit"), 1000);
  EXPECT_EQ(record.at("settings").at("max_radius"), 2.0);

  const RunResult def = run("sins --worlds 2 --seed 5 --system static -o default");
  ASSERT_EQ(def.exit_code, 0) << def.err;
  const nlohmann::json d = nlohmann::json::parse(read_file(dir_ / "default" / "record.json"));
  EXPECT_EQ(d.at("settings").at("step_limit"), amp::nav::kCalibratedScale.step_limit);
  EXPECT_DOUBLE_EQ(d.at("settings").at("max_radius").get<double>(), 2.0 * amp::nav::kCalibratedScale.factor);

  const RunResult limit = run("sins --worlds 2 --seed 5 --scale classic --step-limit 50 --system static -o limit");
  ASSERT_EQ(limit.exit_code, 0) << limit.err;
  EXPECT_EQ(nlohmann::json::parse(read_file(dir_ / "limit" / "record.json")).at("settings").at("step_limit"), 50);
}

TEST_F(CliErrors, SinsUnknownScaleIsOneLine) {
  expect_input_error(run("sins --worlds 2 --scale huge"), {"--scale", "unknown scale 'huge'", "calibrated, classic"});
}

}  // namespace
