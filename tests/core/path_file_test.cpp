// path_file.cpp: paths written as OMPL.app text or YAML, and read back.
#include "amp/core/path_file.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/core/joint_space.hpp"

namespace amp::core {
namespace {

namespace fs = std::filesystem;

class PathFile : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    file_ = fs::temp_directory_path() / ("amp_path_file_" + std::to_string(::getpid()) + "_" + info->name());
  }
  void TearDown() override { fs::remove(file_); }
  void write(const std::string& text) const { std::ofstream(file_) << text; }
  // The FileError message read_path_file throws on the file ("" if none).
  std::string error(const Space& space) const {
    try {
      read_path_file(file_, space);
    } catch (const FileError& e) {
      return e.what();
    }
    return "";
  }
  fs::path file_;
};

TEST_F(PathFile, FormatsOneStatePerLineOrAYamlList) {
  const JointSpace space = make_rn_space({0, 0}, {10, 10});
  const std::vector<State> path = {(State(2) << 1, 2.5).finished(), (State(2) << 0.1, 10).finished()};
  EXPECT_EQ(format_path(space, path, PathFormat::kText), "1 2.5\n0.10000000000000001 10\n");
  EXPECT_EQ(format_path(space, path, PathFormat::kYaml),
            "space: " + std::string(space.kind()) + "\nstates:\n  - [1, 2.5]\n  - [0.10000000000000001, 10]\n");
  EXPECT_EQ(path_format_from_string("path"), PathFormat::kText);
  EXPECT_EQ(path_format_from_string("text"), PathFormat::kText);
  EXPECT_EQ(path_format_from_string("yaml"), PathFormat::kYaml);
  EXPECT_THROW(path_format_from_string("json"), ParameterError);
}

TEST_F(PathFile, BothFormatsReadBackBitForBit) {
  const JointSpace space = make_se2_space(-1, -1, 1, 1, 0.5);
  Rng rng(3);
  std::vector<State> path(7);
  for (State& s : path) space.sample_uniform(rng, s);
  for (const PathFormat f : {PathFormat::kText, PathFormat::kYaml}) {
    write(format_path(space, path, f));
    EXPECT_EQ(read_path_file(file_, space), path);
  }
  // Comments and blank lines are skipped.
  write("# a comment\n\n0.5 0.25 1 # trailing\n  \n-0.5 0 -3\n");
  EXPECT_EQ(read_path_file(file_, space),
            (std::vector<State>{(State(3) << 0.5, 0.25, 1).finished(), (State(3) << -0.5, 0, -3).finished()}));
}

TEST_F(PathFile, BadFilesNameTheFileAndTheLine) {
  const JointSpace space = make_rn_space({0, 0}, {10, 10});
  const std::string f = file_.string();
  write("1 2\n1 2 3\n");
  EXPECT_EQ(error(space), f + ":2: expected 2 numbers per state, got 3");
  write("1 2\n\n1 x\n");
  EXPECT_EQ(error(space), f + ":3: not a list of numbers");
  write("1 2\n11 2\n");
  EXPECT_EQ(error(space), f + ":2: state is outside the space's bounds");
  write("space: rn\nstates:\n  - 1, 2\n");
  EXPECT_EQ(error(space), f + ":3: expected '- [numbers]'");
  write("# nothing\n");
  EXPECT_EQ(error(space), f + ": the path file holds no states");
  fs::remove(file_);
  EXPECT_EQ(error(space), f + ": cannot open path file");
}

}  // namespace
}  // namespace amp::core
