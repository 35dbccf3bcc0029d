#pragma once
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "amp/core/state.hpp"
#include "amp/world/problem.hpp"

namespace amp::roadmap {
class Roadmap;
}

namespace amp::viz {

// A roadmap as drawn: vertices and edges (pairs of vertex indices).
struct RoadmapDrawing {
  std::vector<State> vertices;
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  // Optional, one per vertex: its cluster, drawn in the cluster's colour (cluster_color()).
  std::vector<int> labels;
};

// A region box over the world (UAS), outlined and labelled in its cluster's colour.
struct RegionDrawing {
  Eigen::AlignedBox2d box;
  int cluster = 0;
  std::string label;
};

// A categorical colour per cluster index (10 distinct colours, then repeating).
const char* cluster_color(int cluster);

// The vertices and (each undirected edge once) edges of a roadmap.
RoadmapDrawing drawing_of(const roadmap::Roadmap& roadmap);

struct SceneOptions {
  int width_px = 900;
  std::string title;                          // defaults to the problem's name
  const std::vector<State>* path = nullptr;   // drawn with robot footprints along it
  const RoadmapDrawing* roadmap = nullptr;    // drawn under everything else
  const std::vector<RegionDrawing>* regions = nullptr;  // drawn over the obstacles
  int footprints = 24;                        // robot footprints spread evenly along the path
};

// Draws a problem as SVG: the world (3-D worlds as their top view), the robot at start and goal, and
// optionally a path and a roadmap, with a title and a legend.
std::string render_scene(const world::Problem& problem, const SceneOptions& options);

// Writes text to a file; throws FileError when it cannot.
void write_text_file(const std::string& path, const std::string& text);

}  // namespace amp::viz
