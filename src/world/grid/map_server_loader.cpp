#include "amp/world/map_server_loader.hpp"

#include <string>

#include "amp/core/error.hpp"
#include "amp/world/yaml_fields.hpp"

namespace amp::world {

namespace {

constexpr double kFullScale = 255.0;  // map_server works on 8-bit channel averages
constexpr int kOccupiedValue = 100;
constexpr int kScaleSpan = 98;  // scale mode: value = 1 + 98 * ratio

double threshold(const YamlFields& f, const char* key) {
  const double v = f.number(key);
  if (v < 0.0 || v > 1.0) f.fail(key, "expected a number in [0, 1], got '" + f.node()[key].Scalar() + "'");
  return v;
}

// map_server writes `negate: 0`; YAML booleans are accepted too.
bool negate_flag(const YamlFields& f) {
  if (!f.has("negate")) return false;
  const YAML::Node n = f.node()["negate"];
  const std::string s = n.IsScalar() ? n.Scalar() : std::string("a list or mapping");
  if (s == "0" || s == "false" || s == "False") return false;
  if (s == "1" || s == "true" || s == "True") return true;
  f.fail("negate", "expected 0 or 1, got '" + s + "'");
}

MapMode mode_of(const YamlFields& f) {
  const std::string m = f.string("mode", "trinary");
  if (m == "trinary") return MapMode::kTrinary;
  if (m == "scale") return MapMode::kScale;
  if (m == "raw") return MapMode::kRaw;
  f.fail("mode", "expected trinary, scale or raw, got '" + m + "'");
}

CellState classify(double p, const MapServerInfo& info) {
  if (p > info.occupied_thresh) return CellState::kOccupied;
  if (p < info.free_thresh) return CellState::kFree;
  return CellState::kUnknown;
}

}  // namespace

MapServerInfo read_map_server_yaml(const std::filesystem::path& yaml_file) {
  const YamlFields f(load_yaml_file(yaml_file), yaml_file, "");
  if (!f.is_map()) f.fail("", "expected a map_server mapping (image, resolution, origin, ...)");
  MapServerInfo info;
  info.image = f.file_path("image");
  info.resolution = f.positive("resolution");
  const std::vector<double> origin = f.numbers("origin", 3);
  if (origin[2] != 0.0) {
    f.fail("origin", "rotated maps are not supported: yaw must be 0, got " + std::to_string(origin[2]));
  }
  info.origin = {origin[0], origin[1]};
  info.negate = negate_flag(f);
  info.occupied_thresh = threshold(f, "occupied_thresh");
  info.free_thresh = threshold(f, "free_thresh");
  if (info.free_thresh >= info.occupied_thresh) {
    f.fail("free_thresh", "must be below occupied_thresh " + std::to_string(info.occupied_thresh) + ", got " +
                              std::to_string(info.free_thresh));
  }
  info.mode = mode_of(f);
  return info;
}

OccupancyGrid grid_from_image(const PgmImage& image, const MapServerInfo& info) {
  OccupancyGrid grid(image.width, image.height, info.resolution, info.origin);
  const double to_8bit = kFullScale / image.maxval;
  for (int row = 0; row < image.height; ++row) {
    const int cy = image.height - 1 - row;  // the image's top row is the map's largest y
    for (int cx = 0; cx < image.width; ++cx) {
      double color = image.at(cx, row) * to_8bit;
      if (info.negate) color = kFullScale - color;
      if (info.mode == MapMode::kRaw) {
        const int raw = static_cast<int>(color);  // map_server truncates into an unsigned char
        const CellState s = raw <= kOccupiedValue ? classify(raw / 100.0, info) : CellState::kUnknown;
        grid.set_state(cx, cy, s);
        grid.set_value(cx, cy, static_cast<std::int8_t>(static_cast<std::uint8_t>(raw)));
        continue;
      }
      const double occ = (kFullScale - color) / kFullScale;
      const CellState s = classify(occ, info);
      grid.set_state(cx, cy, s);
      const std::size_t i = static_cast<std::size_t>(row) * image.width + cx;
      const bool transparent = !image.transparent.empty() && image.transparent[i] != 0;
      if (s == CellState::kUnknown && info.mode == MapMode::kScale && !transparent) {
        const double ratio = (occ - info.free_thresh) / (info.occupied_thresh - info.free_thresh);
        grid.set_value(cx, cy, static_cast<std::int8_t>(1 + static_cast<int>(kScaleSpan * ratio)));
      }
    }
  }
  return grid;
}

OccupancyGrid load_map_server(const std::filesystem::path& yaml_file) {
  const MapServerInfo info = read_map_server_yaml(yaml_file);
  return grid_from_image(read_map_image(info.image, info.mode), info);
}

}  // namespace amp::world
