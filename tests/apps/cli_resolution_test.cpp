// A resolution below the documented floor (1e-9 of the extent) through the real `amp` binary: exit
// code 1 and one stderr line naming the file and the field, before any planning.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include "support/source_tree.hpp"

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::StartsWith;

// A guard, not a measurement: a hang becomes a failed test (exit 124) instead of a stuck suite.
constexpr int kHangGuardSeconds = 120;

const fs::path kAmp = fs::path(AMP_BINARY_DIR) / "bin" / "amp";
const fs::path kData = fs::path(AMP_SOURCE_DIR) / "tests" / "apps" / "data";

TEST(CliResolution, TinyResolutionIsOneLineNamingTheField) {
  ASSERT_TRUE(fs::is_regular_file(kAmp)) << kAmp << " is missing: build the amp_cli target first";
  const fs::path dir = fs::temp_directory_path() / ("amp_cli_resolution_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path problem = kData / "resolution_tiny.yaml";
  const std::string cmd = "cd '" + dir.string() + "' && timeout " + std::to_string(kHangGuardSeconds) + " '" +
                          kAmp.string() + "' plan '" + problem.string() + "' --out out.path 2>stderr.txt >/dev/null";
  const int status = std::system(cmd.c_str());
  std::ifstream in(dir / "stderr.txt");
  std::stringstream err;
  err << in.rdbuf();
  const bool wrote_path = fs::exists(dir / "out.path");
  fs::remove_all(dir);

  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1) << err.str();
  std::string line;
  std::getline(err, line);
  EXPECT_THAT(line, StartsWith("amp: error: " + problem.string() + ": resolution: "));
  EXPECT_THAT(line, HasSubstr("'1e-10'"));
  EXPECT_THAT(line, HasSubstr("1e-9"));
  EXPECT_FALSE(std::getline(err, line)) << "more than one line: " << line;
  EXPECT_FALSE(wrote_path);
}

}  // namespace
