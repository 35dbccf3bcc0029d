// cost_metric.cpp's direction rule and experiment.cpp's `cost_direction:` field: which values of a
// cost are better, by the metric's name unless the experiment says, and a one-line error naming the
// file and the field for a word that is neither.
#include "amp/bench/cost_metric.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "amp/bench/experiment.hpp"
#include "amp/core/error.hpp"
#include "support/source_tree.hpp"

namespace amp::bench {
namespace {

namespace fs = std::filesystem;

TEST(CostDirection, SharesOfWhatWasAchievedAreBetterHigher) {
  for (const std::string name : {"solved_fraction", "queries_solved", "success_rate", "goals.reached", "arrived",
                                 "min_clearance", "path_clearance", "coverage"}) {
    EXPECT_EQ(default_cost_direction(name), CostDirection::kHigher) << name;
  }
}

TEST(CostDirection, CostsAreBetterLower) {
  // lp_successes is a column counting work; "unsolved" is not the word "solved".
  for (const std::string name : {"cd_calls", "wall_time_s", "nodes", "path_length", "lp_successes", "steps_mean",
                                 "distance_ratio_mean", "replans", "unsolved_worlds", "virtual_collisions_mean"}) {
    EXPECT_EQ(default_cost_direction(name), CostDirection::kLower) << name;
  }
}

TEST(CostDirection, WordsRoundTripAndOthersAreRefused) {
  EXPECT_EQ(parse_cost_direction(to_string(CostDirection::kHigher)), CostDirection::kHigher);
  EXPECT_EQ(parse_cost_direction(to_string(CostDirection::kLower)), CostDirection::kLower);
  for (const std::string bad : {"", "up", "Higher", "max", "lower "}) {
    EXPECT_THROW(parse_cost_direction(bad), ParameterError) << "'" << bad << "'";
  }
  EXPECT_TRUE(better(CostDirection::kHigher, 0.9, 0.04));
  EXPECT_TRUE(better(CostDirection::kLower, 0.04, 0.9));
  EXPECT_FALSE(better(CostDirection::kLower, 1.0, 1.0)) << "ties keep the earlier method";
}

class CostDirectionFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("amp-cost-direction-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // An experiment file on walls.yaml with one PRM and the given `cost:` / `cost_direction:` lines.
  fs::path write(const std::string& cost_lines) const {
    const fs::path file = dir_ / "exp.yaml";
    std::ofstream(file) << "name: direction\nruns: 2\n" << cost_lines << "problems: ["
                        << (fs::path(AMP_SOURCE_DIR) / "problems" / "walls.yaml").string() << "]\nplanners: [prm]\n";
    return file;
  }

  fs::path dir_;
};

TEST_F(CostDirectionFile, TheNameDecidesUnlessTheFileSays) {
  EXPECT_EQ(load_experiment(write("")).cost_direction, CostDirection::kLower);  // cd_calls
  EXPECT_EQ(load_experiment(write("cost: solved_fraction\n")).cost_direction, CostDirection::kHigher);
  EXPECT_EQ(load_experiment(write("cost: solved_fraction\ncost_direction: lower\n")).cost_direction,
            CostDirection::kLower);
  EXPECT_EQ(load_experiment(write("cost: replans\ncost_direction: higher\n")).cost_direction, CostDirection::kHigher);
}

TEST_F(CostDirectionFile, TheDirectionChangesNoRunSoNotTheFingerprint) {
  const std::string plain = load_experiment(write("cost: replans\n")).fingerprint;
  EXPECT_EQ(load_experiment(write("cost: replans\ncost_direction: higher\n")).fingerprint, plain);
}

TEST_F(CostDirectionFile, ABadDirectionIsOneLineNamingFileAndField) {
  for (const std::string bad : {"cost_direction: up\n", "cost_direction: [higher]\n", "cost_direction: 1\n"}) {
    try {
      load_experiment(write("cost: solved_fraction\n" + bad));
      ADD_FAILURE() << "accepted " << bad;
    } catch (const Error& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("exp.yaml"), std::string::npos) << what;
      EXPECT_NE(what.find("cost_direction"), std::string::npos) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }
}

}  // namespace
}  // namespace amp::bench
