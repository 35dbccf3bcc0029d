#include "amp/viz/scene_renderer.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>

#include "amp/core/error.hpp"
#include "amp/roadmap/roadmap.hpp"
#include "amp/viz/svg_canvas.hpp"
#include "amp/viz/world_layer.hpp"
#include "amp/world/occupancy_grid.hpp"

namespace amp::viz {

namespace {

// A palette that reads on screen and in print (and for the colour-blind: blue/orange contrast); the
// world's own colours are world_layer.hpp's.
constexpr const char* kStartColor = "#1b9e77";
constexpr const char* kGoalColor = "#d95f02";
constexpr const char* kPathColor = "#2563eb";
constexpr const char* kRoadmapEdge = "#c3cad3";
constexpr const char* kRoadmapNode = "#7b8794";
constexpr const char* kText = "#1f2933";
constexpr int kFooterPx = 44;

// States spread evenly (by space distance) along a path, endpoints included.
std::vector<State> spread_along(const core::Space& space, const std::vector<State>& path, int count) {
  std::vector<State> out;
  if (path.empty() || count < 2) return path;
  double total = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) total += space.distance(path[i - 1], path[i]);
  if (total <= 0.0) return {path.front()};
  const double step = total / (count - 1);
  double along = 0.0, next = 0.0;
  State s;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const double len = space.distance(path[i - 1], path[i]);
    while (next <= along + len + 1e-12 && static_cast<int>(out.size()) < count) {
      space.interpolate(path[i - 1], path[i], len > 0 ? (next - along) / len : 0.0, s);
      out.push_back(s);
      next += step;
    }
    along += len;
  }
  if (static_cast<int>(out.size()) < count) out.push_back(path.back());
  return out;
}

// Which of a world's views a panel draws: the top view (x, y), or a 3-D world's front view (x, z).
enum class Panel { kTop, kFront };

Eigen::Vector2d seen(Panel panel, const Eigen::Vector3d& p) {
  return panel == Panel::kTop ? Eigen::Vector2d(p.x(), p.y()) : Eigen::Vector2d(p.x(), p.z());
}

world::Shapes2d robot_in(Panel panel, const world::Environment& env, const State& s) {
  return panel == Panel::kTop ? env.robot_outline(s) : env.robot_front_outline(s);
}

// The reference point's trace, with states interpolated at the space resolution so arcs look smooth.
std::vector<Eigen::Vector2d> trace(const world::Problem& p, const std::vector<State>& path, Panel panel) {
  std::vector<Eigen::Vector2d> pts;
  State s;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const double d = p.space->distance(path[i], path[i + 1]);
    // Capped as a double: the step count of a long edge at a fine resolution does not fit an int.
    const double steps = std::ceil(d / p.space->resolution());
    const int n = steps > 1.0 ? static_cast<int>(std::min(steps, 200.0)) : 1;
    for (int k = 0; k < n; ++k) {
      p.space->interpolate(path[i], path[i + 1], static_cast<double>(k) / n, s);
      pts.push_back(seen(panel, p.environment->reference_point(s)));
    }
  }
  if (!path.empty()) pts.push_back(seen(panel, p.environment->reference_point(path.back())));
  return pts;
}

// 3-D worlds are drawn see-through so that stacked obstacles (floors, walls) read as darker.
constexpr double kTopViewOpacity = 0.55;

void legend(SvgCanvas& c, bool has_path, bool has_roadmap, bool has_regions, double obstacle_opacity,
            bool has_unknown) {
  double x = 24;
  const double y = c.height_px() - kFooterPx / 2.0;
  auto item = [&](const char* color, const char* label, double opacity) {
    c.rect_px(x, y - 9, 14, 14, Style{color, "none", 0, opacity});
    c.text_px(x + 20, y + 3, label, 13, kText);
    x += 30 + 7.5 * std::string_view(label).size();
  };
  item(kObstacleFill, "obstacle", obstacle_opacity);
  if (has_unknown) item(kUnknownFill, "unknown (blocked)", 1.0);
  item(kStartColor, "start", 0.8);
  item(kGoalColor, "goal", 0.8);
  if (has_path) item(kPathColor, "path", 0.6);
  if (has_roadmap) item(kRoadmapNode, "roadmap", 0.8);
  if (has_regions) item(cluster_color(0), "regions (colour = cluster)", 0.5);
}

}  // namespace

namespace {

void draw_roadmap(SvgCanvas& c, const world::Environment& env, const RoadmapDrawing& rm, Panel panel) {
  c.begin_group("roadmap");
  std::vector<Eigen::Vector2d> pts;
  pts.reserve(rm.vertices.size());
  for (const auto& v : rm.vertices) pts.push_back(seen(panel, env.reference_point(v)));
  for (const auto& [a, b] : rm.edges) c.line(pts[a], pts[b], Style{"none", kRoadmapEdge, 0.7});
  const bool labelled = rm.labels.size() == pts.size();
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (labelled) {
      c.dot(pts[i], 3.2, Style{cluster_color(rm.labels[i]), "#ffffff", 0.6, 0.95});
    } else {
      c.dot(pts[i], 1.6, Style{kRoadmapNode, "none", 0, 0.9});
    }
  }
  c.end_group();
}

void draw_regions(SvgCanvas& c, const std::vector<RegionDrawing>& regions) {
  c.begin_group("regions");
  for (const RegionDrawing& r : regions) {
    c.rect(r.box, Style{cluster_color(r.cluster), "none", 0, 0.10});
    c.rect(r.box, Style{"none", cluster_color(r.cluster), 2.0, 0.9});
  }
  // Labels at the boxes' top-left corners, stepped down by index: overlapping boxes often share
  // a corner (both touch the world's border).
  for (std::size_t i = 0; i < regions.size(); ++i) {
    const RegionDrawing& r = regions[i];
    const Eigen::Vector2d corner = c.to_px(Eigen::Vector2d(r.box.min().x(), r.box.max().y()));
    c.text_px(corner.x() + 4, corner.y() + 14 + 14 * static_cast<double>(i), r.label, 12, cluster_color(r.cluster),
              "start", true);
  }
  c.end_group();
}

void draw_robots(SvgCanvas& c, const world::Problem& problem, const SceneOptions& options, Panel panel) {
  const world::Environment& env = *problem.environment;
  if (options.path != nullptr && !options.path->empty()) {
    c.begin_group("path");
    for (const State& s : spread_along(*problem.space, *options.path, options.footprints)) {
      draw_shapes(c, robot_in(panel, env, s), Style{kPathColor, kPathColor, 0.6, 0.18});
    }
    c.polyline(trace(problem, *options.path, panel), Style{"none", kPathColor, 2.2, 0.95, true});
    c.end_group();
  }
  c.begin_group("start-goal");
  draw_shapes(c, robot_in(panel, env, problem.start()), Style{kStartColor, "#0f5c45", 1.2, 0.8});
  draw_shapes(c, robot_in(panel, env, problem.goal()), Style{kGoalColor, "#8a3d00", 1.2, 0.8});
  for (std::size_t i = 1; i + 1 < problem.seeds.size(); ++i) {
    draw_shapes(c, robot_in(panel, env, problem.seeds[i]), Style{"#7570b3", "#3f3a80", 1.2, 0.8});
  }
  c.dot(seen(panel, env.reference_point(problem.start())), 3.0, Style{"#ffffff", "#0f5c45", 1.5});
  c.dot(seen(panel, env.reference_point(problem.goal())), 3.0, Style{"#ffffff", "#8a3d00", 1.5});
  c.end_group();
}

// One view of the problem in the canvas's world coordinates: workspace, roadmap, obstacles,
// regions (top view only: they are boxes in (x, y)), path, start and goal.
void draw_panel(SvgCanvas& c, const world::Problem& problem, const SceneOptions& options, Panel panel,
                const Eigen::AlignedBox2d& bounds, const world::Outline& outline, double obstacle_opacity) {
  const world::Environment& env = *problem.environment;
  c.begin_group("workspace");
  c.rect(bounds, Style{kWorkspaceFill, kBoundsStroke, 1.5});
  c.end_group();
  if (options.roadmap != nullptr) draw_roadmap(c, env, *options.roadmap, panel);
  draw_obstacles(c, outline, obstacle_opacity);
  if (panel == Panel::kTop && options.regions != nullptr) draw_regions(c, *options.regions);
  draw_robots(c, problem, options, panel);
}

}  // namespace

std::string render_scene(const world::Problem& problem, const SceneOptions& options) {
  const world::Environment& env = *problem.environment;
  const Eigen::AlignedBox3d b3 = env.workspace_bounds();
  const Eigen::AlignedBox2d top(b3.min().head<2>(), b3.max().head<2>());
  const bool front = env.has_front_view();
  // Two views share one canvas and one scale: the front view (x, z) stands right of the top view,
  // a gap between them, and the canvas spans both heights.
  const Eigen::AlignedBox2d side(Eigen::Vector2d(b3.min().x(), b3.min().z()), Eigen::Vector2d(b3.max().x(), b3.max().z()));
  const double gap = 0.08 * top.sizes().x();
  Eigen::AlignedBox2d canvas_box = top;
  if (front) {
    canvas_box.extend(Eigen::Vector2d(b3.max().x() + gap + side.sizes().x(), side.min().y()));
    canvas_box.extend(Eigen::Vector2d(b3.max().x(), side.max().y()));
  }
  SvgCanvas c(canvas_box, options.width_px, front ? 44 : 28, kFooterPx);

  const std::string title = options.title.empty() ? problem.name : options.title;
  const std::string subtitle = std::string(problem.space->kind()) +
                               (front ? ", 3-D world: top view (x, y), front view (x, z)" : "");
  c.text_px(28, 19, title + " (" + subtitle + ")", 15, kText, "start", true);

  const double obstacle_opacity = env.workspace_dimension() == 3 ? kTopViewOpacity : 1.0;
  const world::Outline outline = env.obstacle_outline();
  draw_panel(c, problem, options, Panel::kTop, top, outline, obstacle_opacity);
  if (front) {
    const double shift_px = (top.sizes().x() + gap) * c.scale();
    const Eigen::Vector2d top_left = c.to_px(Eigen::Vector2d(top.min().x(), top.max().y()));
    const Eigen::Vector2d side_left = c.to_px(Eigen::Vector2d(side.min().x(), side.max().y()));
    c.text_px(top_left.x(), top_left.y() - 6, "top view: x right, y up", 12, kText);
    c.text_px(side_left.x() + shift_px, side_left.y() - 6, "front view: x right, z up", 12, kText);
    c.begin_shifted_group("front-view", shift_px, 0.0);
    draw_panel(c, problem, options, Panel::kFront, side, env.obstacle_front_outline(), obstacle_opacity);
    c.end_group();
  }

  const bool has_unknown = outline.grid != nullptr && outline.grid->count(world::CellState::kUnknown) > 0;
  legend(c, options.path != nullptr && !options.path->empty(), options.roadmap != nullptr,
         options.regions != nullptr && !options.regions->empty(), obstacle_opacity, has_unknown);
  return c.str();
}

const char* cluster_color(int cluster) {
  // Tableau 10: distinct at a glance, and readable on the light background.
  static constexpr const char* kPalette[] = {"#4e79a7", "#f28e2b", "#e15759", "#76b7b2", "#59a14f",
                                             "#edc948", "#b07aa1", "#ff9da7", "#9c755f", "#bab0ac"};
  constexpr int n = static_cast<int>(std::size(kPalette));
  return kPalette[((cluster % n) + n) % n];
}

RoadmapDrawing drawing_of(const roadmap::Roadmap& roadmap) {
  RoadmapDrawing d;
  d.vertices = roadmap.states();
  for (std::size_t v = 0; v < roadmap.vertex_count(); ++v) {
    for (const auto& e : roadmap.edges(v)) {
      if (v < e.to) d.edges.emplace_back(v, e.to);
    }
  }
  return d;
}

void write_text_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw FileError(path + ": cannot open for writing");
  out << text;
  if (!out) throw FileError(path + ": write failed");
}

}  // namespace amp::viz
