// The SINS figures (viz/sins_figures.hpp): Figure 5's learning curves and Figure 4's driven world.
#include "amp/viz/sins_figures.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <utility>

#include "amp/viz/charts.hpp"
#include "amp/viz/svg_canvas.hpp"
#include "amp/viz/world_layer.hpp"
#include "figure_legend.hpp"
#include "palette.hpp"

namespace amp::viz {

namespace {

using namespace palette;  // the shared colours, unqualified like the local ones

// The four schema parameters, in the order of SchemaParameters (Tableau 10's).
constexpr const char* kParameterColors[] = {"#e15759", "#59a14f", "#b07aa1", "#f28e2b"};

// Pixel coordinates (y down) on a canvas whose world is [0, w] x [-h, 0], as charts.cpp does.
Eigen::Vector2d px(double x, double y) { return {x, -y}; }

// ---- Figure 5 ----

constexpr int kCols = 3;
constexpr double kCellPx = 340;               // one panel's column, its tick labels included
constexpr double kLeftPadPx = 56, kRightPadPx = 16;
constexpr double kTitlePx = 44;               // the figure's title and subtitle
constexpr double kCaptionPx = 22;             // a panel's caption, above it
constexpr double kPlotPx = 170;               // a panel's plot height
constexpr double kBelowPx = 40;               // tick labels and "world" under a panel
constexpr double kLegendPx = 34;
constexpr std::size_t kDotsUpTo = 25;         // fewer worlds than this: each average is also a dot

const char* system_color(const std::string& system, std::size_t i) {
  if (system == "static") return "#4e79a7";
  if (system == "random") return "#f28e2b";
  if (system == "adaptive") return "#e15759";
  constexpr const char* kOthers[] = {"#59a14f", "#b07aa1", "#76b7b2"};
  return kOthers[i % std::size(kOthers)];
}

struct Panel {
  const char* caption;
  std::function<double(const SinsCurvePoint&)> value;
  bool unit_range;   // 0..1 whatever the data
  bool from_data;    // the axis starts near the data's least value (a ratio >= 1), not at 0
};

const std::vector<Panel>& panels() {
  static const std::vector<Panel> p = {
      {"solved (fraction of worlds)", [](const SinsCurvePoint& s) { return s.solved_fraction; }, true, false},
      {"steps per world", [](const SinsCurvePoint& s) { return s.steps; }, false, false},
      {"distance per world (m)", [](const SinsCurvePoint& s) { return s.distance; }, false, false},
      {"actual / optimal distance (solved)", [](const SinsCurvePoint& s) { return s.distance_ratio; }, false, true},
      {"virtual collisions per world", [](const SinsCurvePoint& s) { return s.virtual_collisions; }, false, false},
      {"time per world (ms)", [](const SinsCurvePoint& s) { return s.time_ms; }, false, false}};
  return p;
}

std::pair<double, double> value_range(const Panel& panel, const std::vector<SinsCurves>& systems) {
  if (panel.unit_range) return {0.0, 1.0};
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (const SinsCurves& s : systems) {
    for (const SinsCurvePoint& p : s.points) {
      const double v = panel.value(p);
      if (!std::isfinite(v)) continue;
      hi = std::max(hi, v);
      if (v > 0.0) lo = std::min(lo, v);
    }
  }
  lo = panel.from_data && std::isfinite(lo) ? lo : 0.0;
  if (!(hi > lo)) hi = lo + 1.0;
  return nice_range(lo, hi, AxisScale::kLinear, 4);
}

void draw_panel(SvgCanvas& c, const Panel& panel, const std::vector<SinsCurves>& systems, std::size_t worlds,
                double left, double top) {
  const double right = left + kCellPx - kLeftPadPx - kRightPadPx, bottom = top + kPlotPx;
  const auto [x_lo, x_hi] = nice_range(0.0, static_cast<double>(std::max<std::size_t>(worlds, 1)), AxisScale::kLinear, 4);
  const ValueAxis x_axis(x_lo, x_hi, AxisScale::kLinear, left, right);
  const auto [y_lo, y_hi] = value_range(panel, systems);
  const ValueAxis y_axis(y_lo, y_hi, AxisScale::kLinear, bottom, top);
  c.begin_group("estimator-panel");
  c.text_px(left, top - 8, panel.caption, 12, kText, "start", true);
  for (const double t : y_axis.ticks(4)) {
    const double y = y_axis.to_px(t);
    c.line(px(left, y), px(right, y), Style{"none", kGridColor, 1.0});
    c.text_px(left - 6, y + 4, compact_number(t), 11, kAxisColor, "end");
  }
  for (const double t : x_axis.ticks(4)) {
    const double x = x_axis.to_px(t);
    c.line(px(x, top), px(x, bottom), Style{"none", kGridColor, 1.0});
    c.text_px(x, bottom + 15, compact_number(t), 11, kAxisColor, "middle");
  }
  c.rect_px(left, top, right - left, kPlotPx, Style{"none", kAxisColor, 1.0});
  c.text_px((left + right) / 2, bottom + 31, "world", 11, kText, "middle");
  for (std::size_t i = 0; i < systems.size(); ++i) {
    const char* color = system_color(systems[i].system, i);
    std::vector<Eigen::Vector2d> line;
    for (std::size_t k = 0; k < systems[i].points.size(); ++k) {
      const double v = panel.value(systems[i].points[k]);
      if (panel.from_data && !(v > 0.0)) continue;  // no world solved yet: no ratio
      line.push_back(px(x_axis.to_px(static_cast<double>(k + 1)), y_axis.to_px(std::isfinite(v) ? v : 0.0)));
    }
    c.begin_group("system-curve");
    c.polyline(line, Style{"none", color, 1.8, 0.9, true});
    if (line.size() < kDotsUpTo) {
      for (const Eigen::Vector2d& p : line) c.dot(p, 2.5, Style{color, "none", 0.0, 0.9});
    }
    c.end_group();
  }
  c.end_group();
}

// ---- Figure 4 ----

constexpr int kRunWidthPx = 760;
constexpr int kRunMarginPx = 46;
constexpr int kRunFooterPx = 58;       // two legend rows
constexpr double kStripShare = 0.32;   // the parameter strip's height, of the box's
constexpr double kGapShare = 0.13;     // between the strip and the box: its step labels
constexpr double kCrossPx = 5.0;
constexpr std::size_t kMaxPathPoints = 4000;  // the path is thinned to this many (file size)

std::vector<Eigen::Vector2d> thinned(const std::vector<Eigen::Vector2d>& pts) {
  if (pts.size() <= kMaxPathPoints) return pts;
  std::vector<Eigen::Vector2d> out;
  const double stride = static_cast<double>(pts.size()) / kMaxPathPoints;
  for (std::size_t i = 0; i < kMaxPathPoints; ++i) out.push_back(pts[static_cast<std::size_t>(i * stride)]);
  out.push_back(pts.back());
  return out;
}

void draw_strip(SvgCanvas& c, const SinsRunDrawing& d, double y0, double strip_h) {
  const double w = d.width;
  const std::size_t steps = d.parameters.size();
  const auto [t_lo, t_hi] = nice_range(0.0, static_cast<double>(std::max<std::size_t>(steps, 1)), AxisScale::kLinear, 6);
  const auto at = [&, lo = t_lo, hi = t_hi](double step, double u) {  // clang 14 captures no bindings
    return Eigen::Vector2d((step - lo) / (hi - lo) * w, y0 + std::clamp(u, 0.0, 1.0) * strip_h);
  };
  c.begin_group("parameter-strip");
  for (const double u : {0.0, 0.5, 1.0}) {
    c.line(at(t_lo, u), at(t_hi, u), Style{"none", kGridColor, 1.0});
    if (u == 0.5) continue;
    const Eigen::Vector2d p = c.to_px(at(t_lo, u));
    c.text_px(p.x() - 6, p.y() + 4, u == 0.0 ? "min" : "max", 10, kAxisColor, "end");
  }
  const ValueAxis ticks(t_lo, t_hi, AxisScale::kLinear, 0.0, 1.0);
  for (const double t : ticks.ticks(6)) {
    c.line(at(t, 0.0), at(t, 1.0), Style{"none", kGridColor, 1.0});
    const Eigen::Vector2d p = c.to_px(at(t, 0.0));
    c.text_px(p.x(), p.y() + 14, compact_number(t), 10, kAxisColor, "middle");
  }
  const Eigen::Vector2d corner = c.to_px(at(t_lo, 1.0)), far = c.to_px(at(t_hi, 0.0));
  c.rect_px(corner.x(), corner.y(), far.x() - corner.x(), far.y() - corner.y(), Style{"none", kAxisColor, 1.0});
  c.text_px(corner.x(), corner.y() - 6, "schema parameters, each over its range", 12, kText, "start", true);
  c.text_px(far.x(), far.y() + 27, "step", 11, kText, "end");
  for (std::size_t j = 0; j < 4; ++j) {
    std::vector<Eigen::Vector2d> line;
    for (std::size_t k = 0; k < steps; ++k) {
      const double u = d.parameters[k][j];
      if (k == 0 || u != d.parameters[k - 1][j]) {
        if (k > 0) line.push_back(at(static_cast<double>(k), d.parameters[k - 1][j]));
        line.push_back(at(static_cast<double>(k), u));
      }
    }
    if (steps > 0) line.push_back(at(static_cast<double>(steps), d.parameters.back()[j]));
    c.polyline(line, Style{"none", kParameterColors[j], 1.5, 0.9, true});
  }
  c.end_group();
}

void draw_world(SvgCanvas& c, const SinsRunDrawing& d) {
  c.begin_group("workspace");
  c.rect(Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(d.width, d.height)),
         Style{kWorkspaceFill, kBoundsStroke, 1.5});
  c.end_group();
  c.begin_group("obstacles");
  double reach = 0.0;  // how far circles stick out of the box
  for (const world::Circle& circle : d.circles) {
    c.circle(circle.center, circle.radius, Style{kObstacleFill});
    reach = std::max(reach, circle.radius);
  }
  c.end_group();
  // The world is the box: the parts of circles outside it are covered (the clutter counts only
  // what lies inside), then the box's outline is drawn again over them.
  c.begin_group("outside-box");
  const double r = reach + 1.0, w = d.width, h = d.height;
  const Style paper{"#ffffff"};
  c.rect(Eigen::AlignedBox2d(Eigen::Vector2d(-r, -r), Eigen::Vector2d(0, h + r)), paper);
  c.rect(Eigen::AlignedBox2d(Eigen::Vector2d(w, -r), Eigen::Vector2d(w + r, h + r)), paper);
  c.rect(Eigen::AlignedBox2d(Eigen::Vector2d(0, -r), Eigen::Vector2d(w, 0)), paper);
  c.rect(Eigen::AlignedBox2d(Eigen::Vector2d(0, h), Eigen::Vector2d(w, h + r)), paper);
  c.rect(Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(w, h)), Style{"none", kBoundsStroke, 1.5});
  c.end_group();
  c.begin_group("goal");
  c.circle(d.goal, d.goal_tolerance, Style{kGoalColor, kGoalColor, 1.0, 0.6});
  c.end_group();
  c.begin_group("start");
  c.circle(d.start, d.robot_radius, Style{kStartColor, kStartColor, 1.0, 0.8});
  c.end_group();
  c.begin_group("driven-path");
  c.polyline(thinned(d.positions), Style{"none", kPathColor, 1.6, 0.9, true});
  if (!d.positions.empty()) {
    const Eigen::Vector2d end = d.positions.back();
    c.circle(end, d.robot_radius, Style{"none", kPathColor, 1.2});
    if (!d.solved) {
      const double r = kCrossPx / c.scale();
      c.line(end + Eigen::Vector2d(-r, -r), end + Eigen::Vector2d(r, r), Style{"none", kStopColor, 2.0});
      c.line(end + Eigen::Vector2d(-r, r), end + Eigen::Vector2d(r, -r), Style{"none", kStopColor, 2.0});
    }
  }
  c.end_group();
}

}  // namespace

std::string sins_learning_svg(const std::vector<SinsCurves>& systems, const std::string& title) {
  std::size_t worlds = 0;
  for (const SinsCurves& s : systems) worlds = std::max(worlds, s.points.size());
  const std::vector<Panel>& ps = panels();
  const int rows = (static_cast<int>(ps.size()) + kCols - 1) / kCols;
  const double width = kCols * kCellPx;
  const double height = kTitlePx + rows * (kCaptionPx + kPlotPx + kBelowPx) + kLegendPx;
  SvgCanvas c(Eigen::AlignedBox2d(Eigen::Vector2d(0, -height), Eigen::Vector2d(width, 0)), static_cast<int>(width), 0, 0);
  c.text_px(kLeftPadPx, 18, title, 14, kText, "start", true);
  c.text_px(kLeftPadPx, 35, "cumulative averages over the worlds so far, every system on the same worlds", 11,
            kAxisColor, "start");
  for (std::size_t p = 0; p < ps.size(); ++p) {
    const int col = static_cast<int>(p) % kCols, row = static_cast<int>(p) / kCols;
    const double left = col * kCellPx + kLeftPadPx;
    const double top = kTitlePx + row * (kCaptionPx + kPlotPx + kBelowPx) + kCaptionPx;
    draw_panel(c, ps[p], systems, worlds, left, top);
  }
  FigureLegend legend(c, height - 14.0, kLeftPadPx, kText);
  for (std::size_t i = 0; i < systems.size(); ++i) legend.item(system_color(systems[i].system, i), systems[i].system, 0.9);
  return c.str();
}

std::string sins_run_svg(const SinsRunDrawing& d, const std::string& title) {
  const double strip_h = kStripShare * d.height, gap = kGapShare * d.height;
  const double y0 = d.height + gap;  // the strip's bottom, in the box's coordinates
  const Eigen::AlignedBox2d all(Eigen::Vector2d(0, 0), Eigen::Vector2d(d.width, y0 + strip_h));
  SvgCanvas c(all, kRunWidthPx, kRunMarginPx, kRunFooterPx);
  draw_world(c, d);
  draw_strip(c, d, y0, strip_h);
  c.text_px(kRunMarginPx, 18, title, 14, kText, "start", true);
  FigureLegend map_legend(c, c.height_px() - 36.0, kRunMarginPx, kText);
  map_legend.item(kStartColor, "start", 0.8);
  map_legend.item(kGoalColor, "goal (within tolerance)", 0.6);
  map_legend.item(kPathColor, "driven path", 0.9);
  if (!d.solved) map_legend.item(kStopColor, "stopped at the step limit");
  FigureLegend parameter_legend(c, c.height_px() - 14.0, kRunMarginPx, kText);
  for (std::size_t j = 0; j < 4; ++j) parameter_legend.item(kParameterColors[j], d.parameter_names[j], 0.9);
  return c.str();
}

}  // namespace amp::viz
