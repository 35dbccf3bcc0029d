#include "amp/viz/world_layer.hpp"

#include <algorithm>

#include "amp/viz/svg_canvas.hpp"
#include "amp/world/occupancy_grid.hpp"

namespace amp::viz {

namespace {

void draw_grid(SvgCanvas& c, const world::OccupancyGrid& g) {
  // Merge each row's blocked cells into runs: far fewer elements than one rect per cell.
  const Style occupied{kObstacleFill, "none", 0, 1.0};
  const Style unknown{kUnknownFill, "none", 0, 1.0};
  for (int y = 0; y < g.height(); ++y) {
    int x = 0;
    while (x < g.width()) {
      const world::CellState s = g.state(x, y);
      int end = x + 1;
      while (end < g.width() && g.state(end, y) == s) ++end;
      if (s != world::CellState::kFree) {
        Eigen::AlignedBox2d box = g.cell_box(x, y);
        box.extend(g.cell_box(end - 1, y));
        c.rect(box, s == world::CellState::kOccupied ? occupied : unknown);
      }
      x = end;
    }
  }
}

}  // namespace

void draw_shapes(SvgCanvas& c, const world::Shapes2d& shapes, const Style& s) {
  for (const auto& p : shapes.polygons) c.polygon(p.vertices, s);
  for (const auto& ci : shapes.circles) c.circle(ci.center, ci.radius, s);
  // Segment walls have no inside: drawn as strokes in the fill colour, two pixels wide.
  if (!shapes.segments.empty()) {
    Style wall = s;
    if (wall.stroke == "none") wall.stroke = wall.fill;
    wall.stroke_width = std::max(2.0, wall.stroke_width);
    for (const auto& seg : shapes.segments) c.line(seg.a, seg.b, wall);
  }
}

void draw_obstacles(SvgCanvas& c, const world::Outline& outline, double opacity) {
  c.begin_group("obstacles", opacity, outline.grid != nullptr);
  if (outline.grid != nullptr) draw_grid(c, *outline.grid);
  // Members are opaque with an outline of their own colour, so the seams between adjacent
  // triangles of a mesh disappear; the group carries the opacity.
  draw_shapes(c, outline.shapes, Style{kObstacleFill, kObstacleFill, 0.8, 1.0});
  c.end_group();
}

}  // namespace amp::viz
