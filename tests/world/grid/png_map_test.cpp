// PNG map images: each colour type against map_server's rules computed by hand, and against the
// same grey values as a PGM (the reader the suite already checks).
#include <png.h>

#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "amp/core/error.hpp"
#include "amp/world/map_server_loader.hpp"

namespace amp::world {
namespace {

namespace fs = std::filesystem;

class PngMapTest : public ::testing::Test {
 protected:
  void SetUp() override {
    static std::atomic<int> counter{0};
    dir_ = fs::temp_directory_path() / ("amp_png_map_test_" + std::to_string(::getpid()) + "_" +
                                        std::to_string(counter++));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // A PNG of `width` x rows, samples row by row (16-bit samples as big-endian pairs of bytes).
  fs::path png(const std::string& name, int width, int height, int color_type, int bit_depth,
               const std::vector<unsigned char>& samples) const {
    const fs::path file = dir_ / name;
    FILE* f = std::fopen(file.c_str(), "wb");
    png_structp w = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(w);
    png_init_io(w, f);
    png_set_IHDR(w, info, width, height, bit_depth, color_type, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    png_write_info(w, info);
    const std::size_t row = samples.size() / static_cast<std::size_t>(height);
    for (int r = 0; r < height; ++r) png_write_row(w, samples.data() + r * row);
    png_write_end(w, nullptr);
    png_destroy_write_struct(&w, &info);
    std::fclose(f);
    return file;
  }
  fs::path map_yaml(const std::string& image, const std::string& mode) const {
    std::ofstream(dir_ / "map.yaml") << "image: " << image << "\nresolution: 0.5\norigin: [0.0, 0.0, 0.0]\n"
                                     << "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\nmode: " << mode << "\n";
    return dir_ / "map.yaml";
  }
  static std::vector<int> values(const OccupancyGrid& g) {  // top row first, as in the image
    std::vector<int> v;
    for (int cy = g.height() - 1; cy >= 0; --cy) {
      for (int cx = 0; cx < g.width(); ++cx) v.push_back(g.value(cx, cy));
    }
    return v;
  }
  fs::path dir_;
};

TEST_F(PngMapTest, EightBitGreyGivesThePgmsCells) {
  const std::vector<unsigned char> grey{0, 255, 128, 254, 100, 200};
  png("img.png", 3, 2, PNG_COLOR_TYPE_GRAY, 8, grey);
  std::ofstream(dir_ / "img.pgm") << "P2\n3 2\n255\n0 255 128\n254 100 200\n";
  for (const char* mode : {"trinary", "scale", "raw"}) {
    const OccupancyGrid from_png = load_map_server(map_yaml("img.png", mode));
    const OccupancyGrid from_pgm = load_map_server(map_yaml("img.pgm", mode));
    EXPECT_EQ(values(from_png), values(from_pgm)) << mode;
  }
  // Trinary by hand: p = (255 - v) / 255 -> occupied, free, unknown / free, unknown, unknown.
  EXPECT_EQ(values(load_map_server(map_yaml("img.png", "trinary"))), (std::vector<int>{100, 0, -1, 0, -1, -1}));
}

TEST_F(PngMapTest, SixteenBitGreyKeepsTheHighByteAsMapServerDoes) {
  // 0xAB12 -> 0xAB = 171, 0x12FF -> 0x12 = 18, 0xFFFF -> 255.
  png("img16.png", 3, 1, PNG_COLOR_TYPE_GRAY, 16, {0xAB, 0x12, 0x12, 0xFF, 0xFF, 0xFF});
  png("img8.png", 3, 1, PNG_COLOR_TYPE_GRAY, 8, {171, 18, 255});
  // Raw mode publishes the byte, read back as a signed OccupancyGrid.data value.
  EXPECT_EQ(values(load_map_server(map_yaml("img16.png", "raw"))), (std::vector<int>{171 - 256, 18, 255 - 256}));
  EXPECT_EQ(values(load_map_server(map_yaml("img16.png", "scale"))),
            values(load_map_server(map_yaml("img8.png", "scale"))));
}

TEST_F(PngMapTest, RgbIsTheMeanOfItsChannels) {
  // (255, 0, 0) -> 85 -> p = .667 occupied; (0, 255, 255) -> 170 -> p = .333: between the
  // thresholds, scale value 1 + int(98 (.333 - .196) / (.65 - .196)) = 1 + int(29.6) = 30;
  // (255, 255, 252) -> 254 -> free.
  png("rgb.png", 3, 1, PNG_COLOR_TYPE_RGB, 8, {255, 0, 0, 0, 255, 255, 255, 255, 252});
  EXPECT_EQ(values(load_map_server(map_yaml("rgb.png", "scale"))), (std::vector<int>{100, 30, 0}));
  EXPECT_EQ(values(load_map_server(map_yaml("rgb.png", "trinary"))), (std::vector<int>{100, -1, 0}));
}

TEST_F(PngMapTest, AlphaIsAveragedInTrinaryModeAndMarksUnknownInScaleMode) {
  // Grey + alpha: (255, 0), (255, 255), (128, 0), (128, 255).
  png("ga.png", 4, 1, PNG_COLOR_TYPE_GRAY_ALPHA, 8, {255, 0, 255, 255, 128, 0, 128, 255});
  // Trinary averages R = G = B = g with alpha: (3 * 255 + 0) / 4 = 191.25 -> p = .25 unknown;
  // 255 -> free; (3 * 128) / 4 = 96 -> p = .624 unknown; 128 -> p = .498 unknown.
  EXPECT_EQ(values(load_map_server(map_yaml("ga.png", "trinary"))), (std::vector<int>{-1, 0, -1, -1}));
  // Scale leaves alpha out: 255 -> free either way; 128 -> p = .498 between the thresholds:
  // transparent -> unknown (-1), opaque -> 1 + int(98 (.498 - .196) / .454) = 1 + int(65.2) = 66.
  EXPECT_EQ(values(load_map_server(map_yaml("ga.png", "scale"))), (std::vector<int>{0, 0, -1, 66}));
  // RGBA the same way.
  png("rgba.png", 2, 1, PNG_COLOR_TYPE_RGB_ALPHA, 8, {128, 128, 128, 0, 128, 128, 128, 255});
  EXPECT_EQ(values(load_map_server(map_yaml("rgba.png", "scale"))), (std::vector<int>{-1, 66}));
}

TEST_F(PngMapTest, TruncatedCorruptOrOversizedPngsGetOneLineErrors) {
  const fs::path good = png("good.png", 8, 8, PNG_COLOR_TYPE_GRAY, 8, std::vector<unsigned char>(64, 255));
  std::ifstream in(good, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto expect_error = [&](const std::string& name, const std::string& content, const std::string& fragment) {
    std::ofstream(dir_ / name, std::ios::binary) << content;
    try {
      load_map_server(map_yaml(name, "trinary"));
      ADD_FAILURE() << "no error for " << name;
    } catch (const FileError& e) {
      const std::string msg = e.what();
      EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
      EXPECT_NE(msg.find(name), std::string::npos) << msg;
      EXPECT_NE(msg.find(fragment), std::string::npos) << msg;
      for (const char c : msg) EXPECT_TRUE(c >= 0x20 && c < 0x7f) << "raw byte in: " << msg;
    }
  };
  expect_error("cut.png", bytes.substr(0, bytes.size() / 2), "PNG");
  expect_error("header.png", bytes.substr(0, 12), "PNG");
  // Width 2^21 in the IHDR (bytes 16..19), over the 2^20 limit per side.
  std::string wide = bytes;
  wide[16] = 0, wide[17] = 0x20, wide[18] = 0, wide[19] = 0;
  expect_error("wide.png", wide, "PNG");
  // Not an image at all, with binary bytes up front: named by hex escapes, never printed raw.
  expect_error("junk.png", std::string("\x01\x02\xff\xfe junk"), "\\x01\\x02\\xff\\xfe");
}

}  // namespace
}  // namespace amp::world
