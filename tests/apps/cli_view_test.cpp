// `amp view`: it writes the page of a planned path and says whether the path is certified; bad input
// (a missing path file, states of the wrong size, no problem) is one line and no page; an existing
// file is kept without --force.
#include <filesystem>
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/cli_errors_fixture.hpp"

namespace {

namespace fs = std::filesystem;
using namespace amp::test;  // CliErrors, run helpers, kData, kExit*
using ::testing::HasSubstr;
using ::testing::StartsWith;

TEST_F(CliErrors, ViewWritesThePageOfAPlannedPath) {
  ASSERT_EQ(run("plan " + data("ok.yaml") + " --out p.path").exit_code, 0);
  const RunResult r = run("view " + data("ok.yaml") + " --path p.path -o page.html");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(r.out, "viewer page written to page.html\n");
  const std::string page = read_file(dir_ / "page.html");
  EXPECT_THAT(page, StartsWith("<!DOCTYPE html>"));
  EXPECT_THAT(page, HasSubstr("path from p.path · "));
  EXPECT_THAT(page, HasSubstr("certified collision-free along its whole length"));
}

TEST_F(CliErrors, ViewWarnsOfAPathThroughAnObstacle) {
  std::ofstream(dir_ / "straight.path") << "1 1\n9 9\n";  // across the rectangle at (5, 5)
  const RunResult r = run("view " + data("ok.yaml") + " --path straight.path -o page.html");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("warning: segment 0 (waypoints 0 to 1) could not be certified"));
  EXPECT_THAT(read_file(dir_ / "page.html"), HasSubstr("This path is NOT certified collision-free"));
}

TEST_F(CliErrors, ViewRefusesBadInputInOneLine) {
  auto expect_refused = [&](const std::string& args, std::initializer_list<std::string> expected) {
    const RunResult r = run(args);
    EXPECT_EQ(r.exit_code, kExitError) << args << "\n" << r.err;
    ASSERT_EQ(lines_of(r.err).size(), 1u) << args << "\n" << r.err;
    EXPECT_THAT(r.err, StartsWith("amp: error: "));
    for (const std::string& e : expected) EXPECT_THAT(r.err, HasSubstr(e)) << args;
    EXPECT_FALSE(fs::exists(dir_ / "page.html")) << args;
  };
  expect_refused("view " + data("ok.yaml") + " --path no_such.path -o page.html", {"no_such.path"});
  std::ofstream(dir_ / "wide.path") << "1 1 0\n9 9 0\n";
  expect_refused("view " + data("ok.yaml") + " --path wide.path -o page.html", {"wide.path"});
  expect_refused("view -o page.html", {"PROBLEM"});
  expect_refused("view " + data("ok.yaml") + " -o no_such_dir/page.html", {"-o", "no_such_dir"});
}

TEST_F(CliErrors, ViewKeepsAnExistingFileWithoutForce) {
  const std::string precious = "my own page\n";
  std::ofstream(dir_ / "page.html") << precious;
  const RunResult r = run("view " + data("ok.yaml") + " -o page.html");
  EXPECT_EQ(r.exit_code, kExitError);
  ASSERT_EQ(lines_of(r.err).size(), 1u) << r.err;
  EXPECT_THAT(r.err, HasSubstr("--force"));
  EXPECT_EQ(read_file(dir_ / "page.html"), precious);
  ASSERT_EQ(run("view " + data("ok.yaml") + " -o page.html --force").exit_code, 0);
  EXPECT_THAT(read_file(dir_ / "page.html"), HasSubstr("No path: the robot is shown at the start"));
}

}  // namespace
