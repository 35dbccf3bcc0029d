#pragma once
#include <filesystem>

#include <Eigen/Core>

#include "amp/world/occupancy_grid.hpp"

namespace amp::world {

// Loads a MovingAI benchmark map (https://movingai.com/benchmarks/formats.html):
//   type octile / height H / width W / map / then H rows of W characters.
// '.', 'G' and 'S' are passable; '@', 'O', 'T' and 'W' are blocked (W is water: impassable for
// our ground robot). The first text row is the map's largest y. Cells are `resolution` wide with
// the lower-left corner at `origin`. Throws FileError (file, line, value) for a bad header, a wrong
// row count or row length, or an unknown character.
OccupancyGrid load_movingai(const std::filesystem::path& file, double resolution = 1.0,
                            const Eigen::Vector2d& origin = Eigen::Vector2d::Zero());

}  // namespace amp::world
