// `amp plan` and `amp render` output files (refused overwrites, bad destinations) and the JSON record;
// the studies' output folders.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/cli_errors_fixture.hpp"
#include "support/source_tree.hpp"

namespace {

namespace fs = std::filesystem;
using namespace amp::test;  // CliErrors, run helpers, kData, kExit*
using ::testing::HasSubstr;
using ::testing::StartsWith;

// ---- output files

TEST_F(CliErrors, OutRefusesToOverwriteWithoutForce) {
  const std::string precious = "my own notes\n";
  std::ofstream(dir_ / "keep.path") << precious;
  const RunResult r = run("plan " + data("ok.yaml") + " --out keep.path");
  EXPECT_EQ(r.exit_code, kExitError);
  ASSERT_EQ(lines_of(r.err).size(), 1u) << r.err;
  EXPECT_THAT(r.err, StartsWith("amp: error: --out: "));
  EXPECT_THAT(r.err, HasSubstr("keep.path"));
  EXPECT_THAT(r.err, HasSubstr("--force"));
  EXPECT_EQ(read_file(dir_ / "keep.path"), precious);
}

TEST_F(CliErrors, OutOverwritesWithForce) {
  std::ofstream(dir_ / "keep.path") << "my own notes\n";
  const RunResult r = run("plan " + data("ok.yaml") + " --out keep.path --force");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  // The file now holds the path: the first state is the problem's start (1, 1).
  const std::vector<std::string> lines = lines_of(read_file(dir_ / "keep.path"));
  ASSERT_GE(lines.size(), 2u);
  EXPECT_EQ(lines.front(), "1 1");
  EXPECT_EQ(lines.back(), "9 9");
}

TEST_F(CliErrors, OutIsADirectory) {
  fs::create_directory(dir_ / "out.path");
  const RunResult r = plan(data("ok.yaml"));
  EXPECT_EQ(r.exit_code, kExitError);
  ASSERT_EQ(lines_of(r.err).size(), 1u) << r.err;
  EXPECT_THAT(r.err, StartsWith("amp: error: --out: "));
  EXPECT_THAT(r.err, HasSubstr("is a directory"));
  EXPECT_TRUE(fs::is_empty(dir_ / "out.path"));
  EXPECT_FALSE(fs::exists(dir_ / "out.svg"));
}

TEST_F(CliErrors, SvgIntoMissingDirectory) {
  const RunResult r = run("plan " + data("ok.yaml") + " --out out.path --svg no_such_dir/out.svg");
  expect_input_error(r, {"--svg", "no_such_dir", "does not exist"});
  EXPECT_FALSE(fs::exists(dir_ / "no_such_dir"));
}

// The three studies check their output folder the same way (study::check_output_dir), before any
// work: a missing parent, a file in the folder's place, an output file that exists without --force.
TEST_F(CliErrors, StudiesRefuseTheirOutputFolderTheSameWay) {
  const std::string problems = std::string(AMP_SOURCE_DIR) + "/problems/";
  const std::vector<std::string> commands = {"explore " + problems + "office-map.yaml --steps 100 --queries 0",
                                             "navigate " + problems + "policy-lab.yaml --runs 1",
                                             "sins --worlds 1"};
  std::ofstream(dir_ / "a_file") << "x";
  fs::create_directory(dir_ / "full");
  std::ofstream(dir_ / "full" / "record.json") << "{}";
  for (const std::string& c : commands) {
    expect_input_error(run(c + " -o no_such_dir/out"), {"-o", "directory 'no_such_dir' does not exist"});
    expect_input_error(run(c + " -o a_file"), {"-o", "'a_file' is a file, expected a directory"});
    expect_input_error(run(c + " -o full"), {"-o", "record.json", "already exists", "--force"});
    EXPECT_FALSE(fs::exists(dir_ / "no_such_dir"));
    EXPECT_EQ(read_file(dir_ / "full" / "record.json"), "{}");
  }
}

TEST_F(CliErrors, SvgAndOutNameTheSameFile) {
  const RunResult r = run("plan " + data("ok.yaml") + " --out out.path --svg ./out.path");
  expect_input_error(r, {"--svg", "out.path", "--out"});
}

TEST_F(CliErrors, RenderWithoutOutput) {
  const RunResult r = run("render " + data("ok.yaml"));
  expect_input_error(r, {"--output", "required"});
}

TEST_F(CliErrors, RenderWithMalformedPathFile) {
  const RunResult r = run("render " + data("ok.yaml") + " --path " + data("bad_path.txt") + " -o out.svg");
  expect_input_error(r, {"bad_path.txt:2", "expected 2 numbers per state, got 3"});
}


// ---- machine-readable output

TEST_F(CliErrors, JsonRecordIsValidJson) {
  const RunResult r = run("plan " + data("ok.yaml") + " --json --seed 3");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);  // throws (fails the test) on anything but JSON
  EXPECT_EQ(j.at("status"), "solved");
  EXPECT_EQ(j.at("seed"), 3);
  EXPECT_GT(j.at("cd_calls").get<long long>(), 0);
  EXPECT_EQ(j.at("cd_calls").get<long long>(), j.at("cd_calls_training").get<long long>() +
                                                    j.at("cd_calls_planning").get<long long>() +
                                                    j.at("cd_calls_query").get<long long>());
}

}  // namespace
