#include "amp/study/output_dir.hpp"

#include <fstream>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"

namespace amp::study {
namespace {

namespace fs = std::filesystem;

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

class OutputDir : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("amp_output_dir_" + std::to_string(::getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_);
  }
  void TearDown() override { fs::remove_all(root_); }
  fs::path root_;
};

TEST_F(OutputDir, ANewFolderInAnExistingOneIsFine) {
  EXPECT_EQ(error_of([&] { check_output_dir(root_ / "new", {"record.json"}, false, "-o"); }), "no error");
  create_output_dir(root_ / "new" / "deeper");
  EXPECT_TRUE(fs::is_directory(root_ / "new" / "deeper"));
}

TEST_F(OutputDir, RefusesAFileAMissingParentAndAnExistingOutputWithoutForce) {
  std::ofstream(root_ / "file") << "x";
  EXPECT_EQ(error_of([&] { check_output_dir(root_ / "file", {"a"}, false, "-o"); }),
            "-o: '" + (root_ / "file").string() + "' is a file, expected a directory");
  EXPECT_EQ(error_of([&] { check_output_dir(root_ / "no" / "dir", {"a"}, false, "-o"); }),
            "-o: directory '" + (root_ / "no").string() + "' does not exist");
  fs::create_directories(root_ / "out");
  std::ofstream(root_ / "out" / "record.json") << "{}";
  EXPECT_EQ(error_of([&] { check_output_dir(root_ / "out", {"figure.svg", "record.json"}, false, "-o"); }),
            "-o: '" + (root_ / "out" / "record.json").string() + "' already exists (use --force to overwrite it)");
  EXPECT_EQ(error_of([&] { check_output_dir(root_ / "out", {"record.json"}, true, "-o"); }), "no error");
  EXPECT_EQ(error_of([&] { check_writable(root_ / "out", true, "--svg"); }),
            "--svg: '" + (root_ / "out").string() + "' is a directory, expected a file name");
}

}  // namespace
}  // namespace amp::study
