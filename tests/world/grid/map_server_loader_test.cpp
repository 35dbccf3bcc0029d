#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "amp/core/error.hpp"
#include "amp/world/map_server_loader.hpp"

namespace amp::world {
namespace {

namespace fs = std::filesystem;

// A scratch directory per test for hand-written maps.
class MapServerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    static std::atomic<int> counter{0};
    dir_ = fs::temp_directory_path() / ("amp_map_server_test_" + std::to_string(::getpid()) + "_" +
                                        std::to_string(counter++));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name, std::ios::binary) << text;
    return dir_ / name;
  }
  fs::path yaml(const std::string& body) const { return write("map.yaml", body); }

  // Expects FileError whose message contains every fragment.
  static void expect_error(const fs::path& file, std::initializer_list<std::string> fragments) {
    try {
      load_map_server(file);
      ADD_FAILURE() << "no error for " << file;
    } catch (const FileError& e) {
      const std::string msg = e.what();
      EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
      for (const auto& f : fragments) EXPECT_NE(msg.find(f), std::string::npos) << "'" << f << "' not in: " << msg;
    }
  }

  fs::path dir_;
};

// 3 x 2 image; top row is y = 1. Pixels -> p = (255 - v) / 255:
//   0 -> 1.0 occ, 255 -> 0 free, 128 -> 0.498 unknown / 254 -> 0.004 free, 100 -> 0.608 unknown, 200 -> 0.216 unknown
constexpr const char* kP2 = "P2\n# comment\n3 2\n255\n0 255 128\n254 100 200\n";
constexpr const char* kYaml =
    "image: img.pgm\nresolution: 0.5\norigin: [-1.0, 2.0, 0.0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";

std::string p5_bytes(const std::string& header, std::initializer_list<int> bytes) {
  std::string s = header;
  for (int b : bytes) s.push_back(static_cast<char>(b));
  return s;
}

void expect_default_cells(const OccupancyGrid& g) {
  ASSERT_EQ(g.width(), 3);
  ASSERT_EQ(g.height(), 2);
  EXPECT_EQ(g.state(0, 1), CellState::kOccupied);
  EXPECT_EQ(g.state(1, 1), CellState::kFree);
  EXPECT_EQ(g.state(2, 1), CellState::kUnknown);
  EXPECT_EQ(g.state(0, 0), CellState::kFree);
  EXPECT_EQ(g.state(1, 0), CellState::kUnknown);
  EXPECT_EQ(g.state(2, 0), CellState::kUnknown);
  EXPECT_EQ(g.value(0, 1), 100);
  EXPECT_EQ(g.value(1, 1), 0);
  EXPECT_EQ(g.value(2, 1), -1);
}

TEST_F(MapServerTest, AsciiPgmTrinaryTopRowIsLargestY) {
  write("img.pgm", kP2);
  const OccupancyGrid g = load_map_server(yaml(kYaml));
  expect_default_cells(g);
  EXPECT_DOUBLE_EQ(g.resolution(), 0.5);
  EXPECT_EQ(g.count(CellState::kUnknown), 3u);
}

TEST_F(MapServerTest, BinaryPgmGivesTheSameCells) {
  write("img.pgm", p5_bytes("P5\n3 2\n255\n", {0, 255, 128, 254, 100, 200}));
  expect_default_cells(load_map_server(yaml(kYaml)));
}

TEST_F(MapServerTest, SixteenBitBinaryPgmIsBigEndianAndScaled) {
  // v * 257 maps 0..255 onto 0..65535 exactly, so the cells match the 8-bit image.
  std::string data = "P5\n3 2\n65535\n";
  for (int v : {0, 255, 128, 254, 100, 200}) {
    const int w = v * 257;
    data.push_back(static_cast<char>(w >> 8));
    data.push_back(static_cast<char>(w & 0xff));
  }
  write("img.pgm", data);
  expect_default_cells(load_map_server(yaml(kYaml)));
  const PgmImage img = read_pgm(dir_ / "img.pgm");
  EXPECT_EQ(img.maxval, 65535);
  EXPECT_EQ(img.at(2, 0), 128 * 257);
}

TEST_F(MapServerTest, NegateMakesDarkFree) {
  // p = v / 255: 0 free, 255 occ, 128 unknown / 254 occ, 100 (0.392) unknown, 200 (0.784) occ.
  write("img.pgm", kP2);
  std::string y = kYaml;
  y.replace(y.find("negate: 0"), 9, "negate: 1");
  const OccupancyGrid g = load_map_server(yaml(y));
  EXPECT_EQ(g.state(0, 1), CellState::kFree);
  EXPECT_EQ(g.state(1, 1), CellState::kOccupied);
  EXPECT_EQ(g.state(2, 1), CellState::kUnknown);
  EXPECT_EQ(g.state(0, 0), CellState::kOccupied);
  EXPECT_EQ(g.state(1, 0), CellState::kUnknown);
  EXPECT_EQ(g.state(2, 0), CellState::kOccupied);
}

TEST_F(MapServerTest, ThresholdsAreStrict) {
  // 100 -> p = 155/255 = 0.6078: occupied iff occupied_thresh < 0.6078; free iff free_thresh > 0.6078.
  write("img.pgm", "P2 1 1 255 100");
  auto with = [&](double occ, double fr) {
    return load_map_server(yaml("image: img.pgm\nresolution: 1\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: " +
                                std::to_string(occ) + "\nfree_thresh: " + std::to_string(fr) + "\n"))
        .state(0, 0);
  };
  EXPECT_EQ(with(0.60, 0.1), CellState::kOccupied);
  EXPECT_EQ(with(0.61, 0.1), CellState::kUnknown);
  EXPECT_EQ(with(0.95, 0.61), CellState::kFree);
  EXPECT_EQ(with(0.95, 0.60), CellState::kUnknown);
}

TEST_F(MapServerTest, ScaleAndRawModesPublishMapServerValues) {
  write("img.pgm", kP2);
  const OccupancyGrid s = load_map_server(yaml(std::string(kYaml) + "mode: scale\n"));
  // value = 1 + 98 (p - free) / (occ - free): 128 -> 1 + 98 * 0.30204 / 0.454 = 66.2 -> 66.
  EXPECT_EQ(s.value(2, 1), 66);
  EXPECT_EQ(s.value(1, 0), 89);  // p = 0.6078
  EXPECT_EQ(s.value(2, 0), 5);   // p = 0.2157
  EXPECT_EQ(s.value(0, 1), 100);
  EXPECT_EQ(s.value(0, 0), 0);
  EXPECT_EQ(s.state(2, 1), CellState::kUnknown);

  // raw: the pixel itself; as a percentage 0 is free, 100 occupied, anything above 100 unknown.
  const OccupancyGrid r = load_map_server(yaml(std::string(kYaml) + "mode: raw\n"));
  EXPECT_EQ(r.value(0, 1), 0);
  EXPECT_EQ(r.state(0, 1), CellState::kFree);
  EXPECT_EQ(r.value(1, 0), 100);
  EXPECT_EQ(r.state(1, 0), CellState::kOccupied);
  EXPECT_EQ(r.value(2, 0), static_cast<std::int8_t>(200));
  EXPECT_EQ(r.state(2, 0), CellState::kUnknown);
}

TEST_F(MapServerTest, OriginOffsetPlacesCells) {
  write("img.pgm", kP2);
  const OccupancyGrid g = load_map_server(yaml(kYaml));
  EXPECT_TRUE(g.cell_center(0, 0).isApprox(Eigen::Vector2d(-0.75, 2.25)));
  EXPECT_EQ(g.world_to_cell({-0.1, 2.9}), Eigen::Vector2i(1, 1));
  EXPECT_EQ(g.world_to_cell({-1.01, 2.0}), Eigen::Vector2i(-1, 0));
  EXPECT_TRUE(g.extent().min().isApprox(Eigen::Vector2d(-1.0, 2.0)));
  EXPECT_TRUE(g.extent().max().isApprox(Eigen::Vector2d(0.5, 3.0)));
}

TEST_F(MapServerTest, YamlErrorsNameFileAndField) {
  write("img.pgm", kP2);
  const std::string base = kYaml;
  auto without = [&](const std::string& key) {
    std::string y = base;
    const auto at = y.find(key + ":");
    y.erase(at, y.find('\n', at) - at + 1);
    return y;
  };
  for (const std::string key : {"image", "resolution", "origin", "occupied_thresh", "free_thresh"}) {
    expect_error(yaml(without(key)), {"map.yaml", key, "missing"});
  }
  auto replaced = [&](const std::string& key, const std::string& value) {
    std::string y = base;
    const auto at = y.find(key + ":");
    y.replace(at, y.find('\n', at) - at, key + ": " + value);
    return y;
  };
  expect_error(yaml(replaced("occupied_thresh", "1.5")), {"map.yaml", "occupied_thresh", "1.5"});
  expect_error(yaml(replaced("free_thresh", "-0.1")), {"map.yaml", "free_thresh", "-0.1"});
  expect_error(yaml(replaced("free_thresh", "0.65")), {"map.yaml", "free_thresh", "occupied_thresh"});
  expect_error(yaml(replaced("resolution", "0")), {"map.yaml", "resolution", "0"});
  expect_error(yaml(replaced("resolution", "-0.05")), {"map.yaml", "resolution", "-0.05"});
  expect_error(yaml(replaced("origin", "[0, 0, 0.5]")), {"map.yaml", "origin", "yaw"});
  expect_error(yaml(replaced("origin", "[0, 0]")), {"map.yaml", "origin"});
  expect_error(yaml(replaced("negate", "2")), {"map.yaml", "negate", "2"});
  expect_error(yaml(replaced("image", "nowhere.pgm")), {"map.yaml", "image", "nowhere.pgm"});
  expect_error(yaml(base + "mode: fancy\n"), {"map.yaml", "mode", "fancy"});
}

TEST_F(MapServerTest, ImageErrorsNameFileAndValue) {
  const fs::path y = yaml(kYaml);
  write("img.pgm", p5_bytes("P5\n3 2\n255\n", {0, 255, 128, 254, 100}));
  expect_error(y, {"img.pgm", "5 bytes", "needs 6", "truncated"});
  write("img.pgm", p5_bytes("P5\n3 2\n255\n", {0, 255, 128, 254, 100, 200, 7}));
  expect_error(y, {"img.pgm", "7 bytes", "needs 6"});
  write("img.pgm", "P2\n3 2\n255\n0 255 128\n254 100\n");
  expect_error(y, {"img.pgm", "truncated", "5 samples"});
  // Fuzzing found: a header claiming 10^8 pixels over a few bytes allocated the raster first (seconds).
  write("img.pgm", "P2\n10000 10000\n255\n0 7\n");
  expect_error(y, {"img.pgm", "truncated", "10000x10000", "needs 100000000 samples"});
  // Fuzzing found: width x height overflowed a 64-bit integer (undefined behaviour) before the check.
  write("img.pgm", "P2\n6553522555 52265535558\n255\n0\n");
  expect_error(y, {"img.pgm", "6553522555x52265535558", "too large"});
  write("img.pgm", "P2\n3 2\n255\n0 255 128\n254 100 200 9\n");
  expect_error(y, {"img.pgm", "more samples", "9"});
  write("img.pgm", "P2\n3 2\n100\n0 255 128\n254 100 200\n");
  expect_error(y, {"img.pgm", "255", "maxval 100"});
  write("img.pgm", "P2\n3 2\n70000\n0 0 0 0 0 0\n");
  expect_error(y, {"img.pgm", "maxval", "70000"});
  write("img.pgm", "P6\n3 2\n255\n");
  expect_error(y, {"img.pgm", "P6"});
  write("img.pgm", "P2\n3 x\n255\n");
  expect_error(y, {"img.pgm", "height", "x"});
  write("img.pgm", "P5\n3 2\n");
  expect_error(y, {"img.pgm", "maxval"});
  write("img.pgm", "");
  expect_error(y, {"img.pgm"});
}

}  // namespace
}  // namespace amp::world
