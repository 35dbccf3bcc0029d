#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "amp/core/space.hpp"
#include "amp/core/state.hpp"
#include "amp/viz/scene_renderer.hpp"
#include "amp/world/problem.hpp"

namespace amp::viz {

// What a 3-D viewer page shows besides the problem (`amp view`, docs/viewer.md).
struct ViewerContent {
  std::string title;     // empty: the problem's name
  std::string subtitle;  // one line under the title: where the path came from
  // The path the robot plays along (empty: the robot stays at the start).
  std::vector<State> path;
  // Whether `path` is known to be collision-free along its whole length, or why not (shown).
  bool path_certified = false;
  std::string path_failure;
  const RoadmapDrawing* roadmap = nullptr;  // drawn as lines between the vertices' reference points
  // Above this many bytes, the meshes are simplified for display (said in the page).
  std::size_t max_bytes = 20'000'000;
  // About how many frames the slider steps through (each waypoint is one at least).
  std::size_t frames = 300;
};

// One self-contained HTML page (three.js inlined, no network): the world, the robot at start and
// goal, the path as the robot's reference point's trace, and the robot moving along it (play,
// pause, a slider), with orbit and zoom. Works for every world (Environment::scene_model()).
std::string viewer_page(const world::Problem& problem, const ViewerContent& content);

// The content for a path, whichever way it came (a file, a run): checked with
// roadmap::certify_path, so that the page says "certified" only of a path proven collision-free
// along its whole length, and says why not otherwise. `source` becomes the subtitle.
ViewerContent path_content(const world::Problem& problem, std::vector<State> path, const std::string& source);

// The states the slider steps through: every waypoint, and between two the space's interpolation
// at steps of about total length / `frames`. A single waypoint gives one frame.
std::vector<State> viewer_frames(const core::Space& space, const std::vector<State>& path, std::size_t frames);

}  // namespace amp::viz
