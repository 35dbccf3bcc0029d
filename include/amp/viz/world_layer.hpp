#pragma once
#include <string>

#include "amp/world/shapes2d.hpp"
#include "amp/world/world_drawing.hpp"

namespace amp::viz {

class SvgCanvas;
struct Style;

// The world as every picture draws it (render_scene, the PGCS figures), so that one map looks the
// same in all of them: its bounds as a light rectangle, then its obstacles.
inline constexpr const char* kObstacleFill = "#3f4a5a";
inline constexpr const char* kUnknownFill = "#a9b1bc";
inline constexpr const char* kBoundsStroke = "#1f2933";
inline constexpr const char* kWorkspaceFill = "#f7f8fa";

// Polygons and circles in `s`; segment walls (no inside) as strokes in the fill colour.
void draw_shapes(SvgCanvas& c, const world::Shapes2d& shapes, const Style& s);
// The obstacles of `outline` (a map's occupied and unknown cells, then its shapes) in a group of
// their own, with `opacity` for the group (3-D worlds seen from above are drawn see-through).
void draw_obstacles(SvgCanvas& c, const world::Outline& outline, double opacity = 1.0);

}  // namespace amp::viz
