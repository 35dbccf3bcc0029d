#pragma once
#include <cstdint>
#include <filesystem>
#include <vector>

#include <Eigen/Core>

#include "amp/world/occupancy_grid.hpp"

namespace amp::world {

// A greyscale map image: a PGM (P2 ASCII or P5 binary, maxval 1..65535) read by our own parser, or
// a PNG's grey values as map_server computes them (read_png).
struct PgmImage {
  int width = 0;
  int height = 0;
  int maxval = 255;
  std::vector<std::uint16_t> pixels;  // row-major, TOP row first (image order)
  // 1 where a PNG pixel is fully transparent (empty: the image has no alpha, or it was averaged in).
  std::vector<std::uint8_t> transparent;

  std::uint16_t at(int col, int row) const { return pixels[static_cast<std::size_t>(row) * width + col]; }
};

// Throws FileError (file + what + value) for an unreadable file, a bad magic number or header, a
// sample above maxval, and data shorter or longer than the header's width x height.
PgmImage read_pgm(const std::filesystem::path& file);

// map_server's interpretation modes (http://wiki.ros.org/map_server, "YAML format").
enum class MapMode { kTrinary, kScale, kRaw };

// A PNG (grey, grey + alpha, RGB, RGBA or palette; 1 to 16 bits) as map_server's image loader sees
// it: 16-bit samples keep their high byte; the colour channels are averaged into one grey value
// (grey counting as R = G = B); an alpha channel is averaged in too in trinary mode, and otherwise
// kept as `transparent` (a fully transparent pixel in the band between the thresholds is unknown
// in scale mode). Where AMP differs from map_server: palettes are expanded to their colours and
// 1-, 2- and 4-bit grey scaled to 0..255 (map_server would read palette indices and unscaled
// values), and an RGB image without alpha is opaque (map_server reads its blue as alpha). Throws
// FileError (file + one line) for an unreadable, truncated or corrupt file, or one larger than
// 2^28 pixels.
PgmImage read_png(const std::filesystem::path& file, MapMode mode);
// read_png for a file with the PNG signature, read_pgm otherwise.
PgmImage read_map_image(const std::filesystem::path& file, MapMode mode);

// The fields of a map_server YAML file.
struct MapServerInfo {
  std::filesystem::path image;  // absolute, or relative to the YAML file's directory
  double resolution = 0.05;
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();  // yaw must be 0
  bool negate = false;
  double occupied_thresh = 0.65;
  double free_thresh = 0.196;
  MapMode mode = MapMode::kTrinary;
};

// Reads a map_server YAML file (without loading the image). Throws FileError naming the file,
// field and value for missing fields, thresholds outside [0, 1] or free >= occupied, resolution <= 0,
// origin yaw != 0, an unknown mode or a missing image file.
MapServerInfo read_map_server_yaml(const std::filesystem::path& yaml_file);

// Converts an image to a grid exactly as map_server does: with v the pixel scaled to 0..255 (and
// 255 - v when negate), p = (255 - v) / 255; occupied if p > occupied_thresh, free if
// p < free_thresh, unknown otherwise. The value stored per cell is what map_server publishes
// (trinary: 100/0/-1; scale: 100/0/1 + 98 * ratio; raw: v). The image's top row is the map's
// largest y. In raw mode the state follows the published value read as a percentage (0..100,
// above 100 is unknown) against the same thresholds.
OccupancyGrid grid_from_image(const PgmImage& image, const MapServerInfo& info);

// read_map_server_yaml + read_map_image + grid_from_image.
OccupancyGrid load_map_server(const std::filesystem::path& yaml_file);

}  // namespace amp::world
