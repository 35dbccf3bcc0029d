#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "amp/core/error.hpp"
#include "amp/world/movingai_loader.hpp"

namespace amp::world {
namespace {

namespace fs = std::filesystem;

class MovingAiTest : public ::testing::Test {
 protected:
  void SetUp() override {
    static std::atomic<int> counter{0};
    file_ = fs::temp_directory_path() /
            ("amp_movingai_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++) + ".map");
  }
  void TearDown() override { fs::remove(file_); }
  const fs::path& write(const std::string& text) const {
    std::ofstream(file_, std::ios::binary) << text;
    return file_;
  }
  void expect_error(const std::string& text, std::initializer_list<std::string> fragments) const {
    try {
      load_movingai(write(text));
      ADD_FAILURE() << "no error for:\n" << text;
    } catch (const FileError& e) {
      const std::string msg = e.what();
      EXPECT_NE(msg.find(file_.filename().string()), std::string::npos) << msg;
      for (const auto& f : fragments) EXPECT_NE(msg.find(f), std::string::npos) << "'" << f << "' not in: " << msg;
    }
  }
  fs::path file_;
};

constexpr const char* kMap = "type octile\nheight 3\nwidth 4\nmap\n.@GS\nOTW.\n....\n";

TEST_F(MovingAiTest, CharactersAndFirstRowIsLargestY) {
  const OccupancyGrid g = load_movingai(write(kMap));
  ASSERT_EQ(g.width(), 4);
  ASSERT_EQ(g.height(), 3);
  const char* expected[3] = {"....", "###.", ".#.."};  // rows y = 0, 1, 2; '#' blocked
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 4; ++x) {
      const CellState want = expected[y][x] == '#' ? CellState::kOccupied : CellState::kFree;
      EXPECT_EQ(g.state(x, y), want) << x << "," << y;
    }
  }
  EXPECT_EQ(g.count(CellState::kOccupied), 4u);
}

TEST_F(MovingAiTest, ResolutionOriginAndWindowsLineEnds) {
  const OccupancyGrid g = load_movingai(write("type octile\r\nheight 2\r\nwidth 2\r\nmap\r\n@.\r\n..\r\n\r\n"), 0.5,
                                        Eigen::Vector2d(1.0, -1.0));
  EXPECT_EQ(g.state(0, 1), CellState::kOccupied);
  EXPECT_EQ(g.count(CellState::kOccupied), 1u);
  EXPECT_TRUE(g.extent().max().isApprox(Eigen::Vector2d(2.0, 0.0)));
  EXPECT_TRUE(g.cell_center(0, 1).isApprox(Eigen::Vector2d(1.25, -0.25)));
}

TEST_F(MovingAiTest, ErrorsNameLineAndValue) {
  expect_error("type hex\nheight 3\nwidth 4\nmap\n", {"line 1", "octile", "hex"});
  expect_error("type octile\nwidth 4\nheight 3\nmap\n", {"line 2", "height"});
  expect_error("type octile\nheight 3\nwidth four\nmap\n", {"line 3", "width", "four"});
  expect_error("type octile\nheight 0\nwidth 4\nmap\n", {"height", "'0'"});
  expect_error("type octile\nheight 3\nwidth 4\nmaps\n", {"line 4", "map", "maps"});
  expect_error("type octile\nheight 3\nwidth 4\n", {"map"});
  expect_error("type octile\nheight 3\nwidth 4\nmap\n....\n....\n", {"2 rows", "height 3"});
  // Found when reviewing the readers for fuzzing: a 32768x32768 header over a few bytes allocated
  // its 2^30 cells before reading a row.
  expect_error("type octile\nheight 32768\nwidth 32768\nmap\n....\n", {"line 5", "4 characters", "width 32768"});
  expect_error("type octile\nheight 3\nwidth 4\nmap\n....\n.....\n....\n", {"line 6", "5 characters", "width 4"});
  expect_error("type octile\nheight 3\nwidth 4\nmap\n....\n...\n....\n", {"3 characters"});
  expect_error("type octile\nheight 3\nwidth 4\nmap\n....\n..x.\n....\n", {"line 6", "column 2", "'x'"});
  expect_error("type octile\nheight 2\nwidth 4\nmap\n....\n....\n....\n", {"more than", "2 rows"});
  try {
    load_movingai(file_.string() + ".missing");
    ADD_FAILURE();
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot open"), std::string::npos);
  }
}

}  // namespace
}  // namespace amp::world
