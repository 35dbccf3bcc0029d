#include "amp/viz/policy_figures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "amp/core/error.hpp"
#include "amp/viz/charts.hpp"
#include "amp/viz/svg_canvas.hpp"
#include "amp/viz/world_layer.hpp"
#include "caption_fit.hpp"
#include "figure_legend.hpp"
#include "palette.hpp"
#include "world_bounds.hpp"

namespace amp::viz {

namespace {

using namespace palette;  // the shared colours, unqualified like the local ones

constexpr const char* kTraceColor = "#c026d3";  // magenta: apart from the path's blue and the ends' colours
// One colour per velocity profile, in order (Tableau 10's first ones).
constexpr const char* kProfileColors[] = {"#4e79a7", "#e15759", "#59a14f", "#f28e2b", "#b07aa1"};
constexpr int kMarginPx = 28;
constexpr int kFooterPx = 64;       // a caption under the last row of panels, then the legend
constexpr int kPanelWidthPx = 420;  // per column, margins included
constexpr double kPanelGap = 0.16;  // of the world's height and width, between panels (captions)
constexpr int kPanelsPerRow = 2;
constexpr int kCaptionPx = 13, kMinCaptionPx = 9;
constexpr double kCaptionBaselinePx = 18;  // the first line's, below its panel
constexpr double kCaptionRoomPx = 44;      // between rows at least: two caption lines
constexpr double kCrossPx = 5.0;           // half-size of the "stopped" cross

std::string caption(const PolicyPhase& phase) {
  std::string s = phase.name;
  if (phase.waypoints) s += ", " + std::to_string(phase.points.size()) + " waypoints";
  if (phase.value) {
    char v[48];
    std::snprintf(v, sizeof v, ", V = %.2f", *phase.value);
    s += v;
  }
  return s;
}

double heading(const Eigen::Vector2d& from, const Eigen::Vector2d& to, double otherwise) {
  const Eigen::Vector2d d = to - from;
  return d.squaredNorm() > 0.0 ? std::atan2(d.y(), d.x()) : otherwise;
}

// Along the last segment of `path` that has a length; `otherwise` when none has.
double final_heading(const std::vector<Eigen::Vector2d>& path, double otherwise) {
  for (std::size_t i = path.size(); i >= 2; --i) {
    if ((path[i - 1] - path[i - 2]).squaredNorm() > 0.0) return heading(path[i - 2], path[i - 1], otherwise);
  }
  return otherwise;
}

// The rectangle at each waypoint that begins a segment, facing along it: where it must fit through doors.
void draw_waypoint_outlines(SvgCanvas& c, const FootprintOutline& f, const std::vector<Eigen::Vector2d>& pts,
                            double start_heading) {
  c.begin_group("waypoint-footprints");
  double h = start_heading;
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    h = heading(pts[i], pts[i + 1], h);  // a repeated waypoint keeps the heading before it
    draw_footprint(c, f, pts[i], h, Style{"none", kPathColor, 0.8, 0.45});
  }
  c.end_group();
}

void draw_trace(SvgCanvas& c, const PolicyPhasesDrawing& d) {
  if (d.trace.empty()) return;
  c.begin_group("driven");
  c.polyline(d.trace, Style{"none", kTraceColor, 1.2, 0.9, true});
  c.end_group();
  if (d.arrived) return;
  c.begin_group("stopped");
  const double h = kCrossPx / c.scale();  // pixels to world units
  const Eigen::Vector2d& p = d.trace.back();
  c.line(p + Eigen::Vector2d(-h, -h), p + Eigen::Vector2d(h, h), Style{"none", kStopColor, 2.0});
  c.line(p + Eigen::Vector2d(-h, h), p + Eigen::Vector2d(h, -h), Style{"none", kStopColor, 2.0});
  c.end_group();
}

void draw_phase(SvgCanvas& c, const world::Problem& problem, const PolicyPhasesDrawing& d, const PolicyPhase& phase,
                bool last) {
  c.begin_group("workspace");
  c.rect(bounds_2d(problem), Style{kWorkspaceFill, kBoundsStroke, 1.5});
  c.end_group();
  draw_obstacles(c, problem.environment->obstacle_outline());
  const double start_heading = heading(d.start, d.goal, 0.0);  // the robot starts facing the goal
  c.begin_group("ends");
  draw_footprint(c, d.footprint, d.start, start_heading, Style{kStartColor, "#0f5c45", 1.2, 0.6});
  draw_footprint(c, d.footprint, d.goal, final_heading(phase.points, start_heading),
                 Style{kGoalColor, "#8a3b02", 1.2, 0.6});
  c.end_group();
  if (phase.waypoints && !d.footprint.disc) draw_waypoint_outlines(c, d.footprint, phase.points, start_heading);
  c.begin_group("path");
  c.polyline(phase.points, Style{"none", kPathColor, phase.waypoints ? 1.6 : 2.2, 0.9, true});
  c.end_group();
  if (last) draw_trace(c, d);  // over the path it follows, under the waypoints' dots
  if (!phase.waypoints) return;
  c.begin_group("waypoints");
  for (const Eigen::Vector2d& p : phase.points) c.dot(p, 3.2, Style{"#ffffff", kPathColor, 1.6});
  c.end_group();
}

// The caption under a panel whose bottom left corner is at (x, y) pixels, wrapped to its width.
void draw_caption(SvgCanvas& c, double x, double y, double width, const std::string& text) {
  const FittedCaption fit = fit_caption(text, width, kCaptionPx, kMinCaptionPx);
  for (std::size_t k = 0; k < fit.lines.size(); ++k) {
    c.text_px(x, y + kCaptionBaselinePx + 1.25 * fit.size_px * static_cast<double>(k), fit.lines[k], fit.size_px,
              kText);
  }
}

}  // namespace

std::string policy_phases_svg(const world::Problem& problem, const PolicyPhasesDrawing& d, const std::string& title) {
  const Eigen::AlignedBox2d bounds = bounds_2d(problem);
  const Eigen::Vector2d size = bounds.sizes();
  const int n = std::max<int>(1, static_cast<int>(d.phases.size()));
  const int cols = std::min(n, kPanelsPerRow), rows = (n + kPanelsPerRow - 1) / kPanelsPerRow;
  // The canvas's scale follows from its width alone, so the rows can leave room for two caption
  // lines however flat the world is.
  const double scale = (kPanelWidthPx * cols - 2.0 * kMarginPx) / (size.x() * (cols + (cols - 1) * kPanelGap));
  const double row_gap = std::max(kPanelGap * size.y(), kCaptionRoomPx / scale);
  const Eigen::Vector2d step(size.x() * (1.0 + kPanelGap), size.y() + row_gap);
  // One canvas for every panel: the first at the top left, the others shifted by whole panels.
  Eigen::AlignedBox2d all = bounds;
  all.extend(Eigen::Vector2d(bounds.min().x() + (cols - 1) * step.x() + size.x(),
                             bounds.max().y() - (rows - 1) * step.y() - size.y()));
  SvgCanvas c(all, kPanelWidthPx * cols, kMarginPx, kFooterPx);
  c.text_px(kMarginPx, 19, title, 15, kText, "start", true);
  for (int i = 0; i < static_cast<int>(d.phases.size()); ++i) {
    const double dx = (i % kPanelsPerRow) * step.x() * c.scale(), dy = (i / kPanelsPerRow) * step.y() * c.scale();
    const PolicyPhase& phase = d.phases[static_cast<std::size_t>(i)];
    c.begin_shifted_group("phase", dx, dy);
    draw_phase(c, problem, d, phase, i + 1 == static_cast<int>(d.phases.size()));
    c.end_group();
    const Eigen::Vector2d corner = c.to_px(Eigen::Vector2d(bounds.min().x(), bounds.min().y()));
    draw_caption(c, corner.x() + dx, corner.y() + dy, size.x() * c.scale(), caption(phase));
  }
  FigureLegend legend(c, c.height_px() - 16.0, kMarginPx, kText);
  legend.item(kStartColor, "start (footprint)", 0.6);
  legend.item(kGoalColor, "goal", 0.6);
  legend.item(kPathColor, "path and waypoints", 0.9);
  if (!d.trace.empty() && !d.phases.empty()) {
    legend.item(kTraceColor, "driven (first seed)", 0.9);
    if (!d.arrived) legend.item(kStopColor, "stopped");
  }
  return c.str();
}

std::string velocity_profiles_svg(const std::vector<VelocityProfile>& profiles, double time_step,
                                  const std::string& title) {
  if (!(time_step > 0.0)) throw ParameterError("velocity_profiles_svg: time_step must be > 0");
  constexpr int kWidth = 760, kHeight = 340;
  constexpr double kLeft = 70, kRight = 20, kTop = 40, kBottom = 290;
  SvgCanvas c(Eigen::AlignedBox2d(Eigen::Vector2d(0, -kHeight), Eigen::Vector2d(kWidth, 0)), kWidth, 0, 0);
  // Pixel coordinates (y down) on a canvas whose world is [0, w] x [-h, 0], as charts.cpp does.
  const auto px = [](double x, double y) { return Eigen::Vector2d(x, -y); };
  c.text_px(kLeft, 20, title, 14, kText, "start", true);
  double t_max = 0.0, v_max = 0.0;
  for (const VelocityProfile& p : profiles) {
    t_max = std::max(t_max, time_step * static_cast<double>(p.speeds.size()));
    for (const double v : p.speeds) v_max = std::max(v_max, std::isfinite(v) ? v : 0.0);
  }
  const auto [t_lo, t_hi] = nice_range(0.0, std::max(t_max, time_step), AxisScale::kLinear);
  const auto [v_lo, v_hi] = nice_range(0.0, std::max(v_max, 1e-3), AxisScale::kLinear);
  const ValueAxis t_axis(t_lo, t_hi, AxisScale::kLinear, kLeft, kWidth - kRight);
  const ValueAxis v_axis(v_lo, v_hi, AxisScale::kLinear, kBottom, kTop);
  for (const double t : v_axis.ticks(5)) {
    c.line(px(kLeft, v_axis.to_px(t)), px(kWidth - kRight, v_axis.to_px(t)), Style{"none", kGridColor, 1.0});
    c.text_px(kLeft - 6, v_axis.to_px(t) + 4, compact_number(t), 11, kAxisColor, "end");
  }
  for (const double t : t_axis.ticks(8)) {
    c.line(px(t_axis.to_px(t), kTop), px(t_axis.to_px(t), kBottom), Style{"none", kGridColor, 1.0});
    c.text_px(t_axis.to_px(t), kBottom + 15, compact_number(t), 11, kAxisColor, "middle");
  }
  c.rect_px(kLeft, kTop, kWidth - kRight - kLeft, kBottom - kTop, Style{"none", kAxisColor, 1.0});
  c.text_px((kLeft + kWidth - kRight) / 2, kBottom + 32, "time (s)", 12, kText, "middle");
  c.text_px(14, kTop - 8, "speed (m/s)", 12, kText, "start");
  FigureLegend legend(c, kHeight - 12.0, kLeft, kText);
  for (std::size_t i = 0; i < profiles.size(); ++i) {
    const char* color = kProfileColors[i % std::size(kProfileColors)];
    std::vector<Eigen::Vector2d> line{px(t_axis.to_px(0.0), v_axis.to_px(0.0))};  // from rest
    for (std::size_t k = 0; k < profiles[i].speeds.size(); ++k) {
      const double v = profiles[i].speeds[k];
      line.push_back(px(t_axis.to_px(time_step * static_cast<double>(k + 1)), v_axis.to_px(std::isfinite(v) ? v : 0.0)));
    }
    c.begin_group("profile");
    c.polyline(line, Style{"none", color, 1.6, 0.9, true});
    c.end_group();
    legend.item(color, profiles[i].label, 0.9);
  }
  return c.str();
}

}  // namespace amp::viz
