#pragma once
// The fixture of the CLI error tests (tests/apps/cli_*_test.cpp): bad input through the real `amp`
// binary must end with exit code 1 and exactly one stderr line `amp: error: <file>: <field>: <what>`
// (no crash, hang or silent wrong answer), and must write no output file. Each test runs `amp` in a
// scratch directory of its own.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include "support/source_tree.hpp"

namespace amp::test {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::StartsWith;

inline constexpr int kExitError = 1;
inline constexpr int kExitNotSolved = 2;
// A guard, not a measurement: a hang becomes a failed test (exit 124) instead of a stuck suite.
inline constexpr int kHangGuardSeconds = 120;

inline const fs::path kAmp = fs::path(AMP_BINARY_DIR) / "bin" / "amp";
inline const fs::path kData = fs::path(AMP_SOURCE_DIR) / "tests" / "apps" / "data";

struct RunResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

inline std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// A data file's path, quoted for the shell (built in steps: GCC 12 warns (-Wrestrict) about "'" + s).
inline std::string data(const std::string& name) {
  std::string quoted = "'";
  quoted += (kData / name).string();
  quoted += '\'';
  return quoted;
}

class CliErrors : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(fs::is_regular_file(kAmp)) << kAmp << " is missing: build the amp_cli target first";
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("amp_cli_errors_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::permissions(dir_ / "locked.yaml", fs::perms::owner_all, ec);
    fs::remove_all(dir_, ec);
  }

  // Runs `amp <args>` inside the test's scratch directory, capturing stdout, stderr and the exit code.
  // `wrapper` goes between the hang guard and the binary (e.g. to drop root privileges).
  RunResult run(const std::string& args, const std::string& wrapper = "") const {
    const std::string cmd = "cd '" + dir_.string() + "' && timeout " + std::to_string(kHangGuardSeconds) + " " +
                            wrapper + " '" + kAmp.string() + "' " + args + " >stdout.txt 2>stderr.txt";
    const int status = std::system(cmd.c_str());
    RunResult r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = read_file(dir_ / "stdout.txt");
    r.err = read_file(dir_ / "stderr.txt");
    fs::remove(dir_ / "stdout.txt");
    fs::remove(dir_ / "stderr.txt");
    return r;
  }

  // `amp plan <problem> <extra>` asked to write a path and a picture into the scratch directory.
  RunResult plan(const std::string& problem, const std::string& extra = "") const {
    return run("plan " + problem + " --out out.path --svg out.svg " + extra);
  }

  // Exit code 1, one stderr line `amp: error: ...` holding every `expected` text, no output files.
  void expect_input_error(const RunResult& r, std::initializer_list<std::string> expected) const {
    EXPECT_EQ(r.exit_code, kExitError) << "stderr: " << r.err;
    const std::vector<std::string> lines = lines_of(r.err);
    ASSERT_EQ(lines.size(), 1u) << "stderr: " << r.err;
    EXPECT_THAT(lines[0], StartsWith("amp: error: "));
    EXPECT_THAT(lines[0], ::testing::Not(HasSubstr("internal")));
    for (const std::string& e : expected) EXPECT_THAT(lines[0], HasSubstr(e));
    EXPECT_FALSE(fs::exists(dir_ / "out.path"));
    EXPECT_FALSE(fs::exists(dir_ / "out.svg"));
  }

  fs::path dir_;
};

// A bundled problem's path (problems/<name>), quoted for the shell.
inline std::string bundled(const std::string& name) {
  std::string quoted = "'";
  quoted += (fs::path(AMP_SOURCE_DIR) / "problems" / name).string();
  quoted += '\'';
  return quoted;
}

}  // namespace amp::test
