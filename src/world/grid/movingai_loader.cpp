#include "amp/world/movingai_loader.hpp"

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "amp/core/error.hpp"

namespace amp::world {

namespace {

// A sanity limit so that a corrupt header cannot request gigabytes.
constexpr long long kMaxSide = 1 << 15;

class MovingAiReader {
 public:
  explicit MovingAiReader(const std::filesystem::path& file) : file_(file), in_(file) {
    if (!in_) throw FileError(file.string() + ": cannot open map file");
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw FileError(file_.string() + ": line " + std::to_string(line_no_) + ": " + what);
  }

  // The next line without its trailing '\r' (files from Windows); false at end of file.
  bool next_line(std::string& line) {
    if (!std::getline(in_, line)) return false;
    ++line_no_;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return true;
  }

  // Reads "<key> <value>" and returns the value text.
  std::string header_field(const char* key) {
    std::string line;
    if (!next_line(line)) fail(std::string("truncated header: missing '") + key + "'");
    std::istringstream words(line);
    std::string k, v, extra;
    words >> k >> v;
    if (k != key || v.empty() || (words >> extra)) {
      fail(std::string("expected '") + key + " <value>', got '" + line + "'");
    }
    return v;
  }

  int dimension(const char* key) {
    const std::string v = header_field(key);
    long long n = 0;
    for (char c : v) {
      if (c < '0' || c > '9' || n > kMaxSide) fail(std::string(key) + ": expected a positive integer, got '" + v + "'");
      n = n * 10 + (c - '0');
    }
    if (n < 1 || n > kMaxSide) fail(std::string(key) + ": expected 1.." + std::to_string(kMaxSide) + ", got '" + v + "'");
    return static_cast<int>(n);
  }

  int line_no() const { return line_no_; }

 private:
  std::filesystem::path file_;
  std::ifstream in_;
  int line_no_ = 0;
};

bool passable(char c) { return c == '.' || c == 'G' || c == 'S'; }
bool impassable(char c) { return c == '@' || c == 'O' || c == 'T' || c == 'W'; }

}  // namespace

OccupancyGrid load_movingai(const std::filesystem::path& file, double resolution, const Eigen::Vector2d& origin) {
  MovingAiReader r(file);
  const std::string type = r.header_field("type");
  if (type != "octile") r.fail("type: expected 'octile', got '" + type + "'");
  const int height = r.dimension("height");
  const int width = r.dimension("width");
  std::string line;
  if (!r.next_line(line) || line != "map") r.fail("expected 'map', got '" + line + "'");

  // Every row is read and checked before the grid is allocated: a header over a few bytes may claim
  // 2^30 cells. The rows held meanwhile are no larger than the file.
  std::vector<std::string> rows;
  for (int row = 0; row < height; ++row) {
    if (!r.next_line(line)) {
      r.fail("map has " + std::to_string(row) + " rows, header says height " + std::to_string(height));
    }
    if (static_cast<int>(line.size()) != width) {
      r.fail("row " + std::to_string(row) + " has " + std::to_string(line.size()) + " characters, header says width " +
             std::to_string(width));
    }
    for (int cx = 0; cx < width; ++cx) {
      const char c = line[static_cast<std::size_t>(cx)];
      if (!passable(c) && !impassable(c)) {
        r.fail("row " + std::to_string(row) + ", column " + std::to_string(cx) + ": unknown map character '" +
               std::string(1, c) + "'");
      }
    }
    rows.push_back(std::move(line));
  }
  OccupancyGrid grid(width, height, resolution, origin);
  for (int row = 0; row < height; ++row) {
    const int cy = height - 1 - row;  // the first text row is the largest y
    for (int cx = 0; cx < width; ++cx) {
      if (impassable(rows[static_cast<std::size_t>(row)][static_cast<std::size_t>(cx)])) {
        grid.set_state(cx, cy, CellState::kOccupied);
      }
    }
  }
  // Trailing blank lines are harmless; any further map text means the height is wrong.
  while (r.next_line(line)) {
    if (line.find_first_not_of(" \t") != std::string::npos) {
      r.fail("map has more than the header's " + std::to_string(height) + " rows");
    }
  }
  return grid;
}

}  // namespace amp::world
