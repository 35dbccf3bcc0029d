#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "amp/core/error.hpp"
#include "amp/world/problem.hpp"

namespace amp::world {
namespace {

namespace fs = std::filesystem;

class ProblemDefaults : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("amp_problem_defaults_test_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  Problem load(const std::string& defaults) {
    const fs::path file = dir_ / "p.yaml";
    std::ofstream(file) << "bounds: {min: [0, 0], max: [10, 10]}\n"
                           "robot: {type: point}\n"
                           "seeds: [[1, 1], [9, 9], [1, 9]]\n"
                        << defaults;
    return load_problem(file);
  }

  fs::path dir_;
};

TEST_F(ProblemDefaults, EdgeCheckIsDiscreteUnlessTheFileSaysCertified) {
  EXPECT_EQ(load("").defaults.edge_check, core::EdgeCheckMode::kDiscrete);
  EXPECT_EQ(load("edge_check: certified\n").defaults.edge_check, core::EdgeCheckMode::kCertified);
  EXPECT_EQ(load("edge_check: discrete\n").defaults.edge_check, core::EdgeCheckMode::kDiscrete);
  EXPECT_THROW(load("edge_check: exact\n"), FileError);
}

TEST_F(ProblemDefaults, PlannerParametersAreKeptAsWritten) {
  const Problem p = load("defaults: {planner: prm-l, params: {steps: 512, n: 0.3}}\n");
  EXPECT_EQ(p.defaults.planner, "prm-l");
  ASSERT_EQ(p.defaults.params.size(), 2u);
  EXPECT_EQ(p.defaults.params.at("steps"), "512");
  EXPECT_EQ(p.defaults.params.at("n"), "0.3");
  EXPECT_EQ(p.seeds.size(), 3u);
}

TEST_F(ProblemDefaults, BadParamsAreFileErrors) {
  EXPECT_THROW(load("defaults: {params: [1, 2]}\n"), FileError);
  EXPECT_THROW(load("defaults: {params: {steps: [1, 2]}}\n"), FileError);
  try {
    load("defaults:\n  params:\n    steps: 512\n    steps: 128\n");
    FAIL() << "a duplicated parameter must be refused";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("duplicate"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace amp::world
