#include "amp/viz/pgcs_figures.hpp"

#include <algorithm>
#include <cstdio>

#include "amp/viz/scene_renderer.hpp"
#include "amp/viz/svg_canvas.hpp"
#include "amp/viz/world_layer.hpp"
#include "figure_legend.hpp"
#include "world_bounds.hpp"

namespace amp::viz {

namespace {

constexpr const char* kText = "#1f2933";
constexpr const char* kTrace = "#9aa5b1";
constexpr const char* kCentre = "#1f2933";
constexpr const char* kLegalEdge = "#7b8794";
constexpr const char* kIllegalEdge = "#d62728";
constexpr const char* kStartColor = "#1b9e77";
constexpr const char* kTargetColor = "#d95f02";
constexpr const char* kClusterColor = "#4e79a7";
constexpr const char* kAppeared = "#b45309";  // obstacles that appeared while exploring
constexpr int kMarginPx = 28;
constexpr int kFooterPx = 44;
constexpr double kPanelGap = 0.06;    // of the world's width, between Figure 1's two panels
constexpr double kCrossPx = 4.5;      // half-size of a replan cross
constexpr std::size_t kMaxTracePoints = 4000;  // the trace is thinned to this many (file size)

void draw_world(SvgCanvas& c, const world::Problem& problem, const PgcsDrawing& d) {
  c.begin_group("workspace");
  c.rect(bounds_2d(problem), Style{kWorkspaceFill, kBoundsStroke, 1.5});
  c.end_group();
  draw_obstacles(c, problem.environment->obstacle_outline());
  if (d.appeared.empty()) return;
  c.begin_group("appeared");
  for (const world::Shapes2d& shapes : d.appeared) draw_shapes(c, shapes, Style{kAppeared, kAppeared, 0.8, 0.9});
  c.end_group();
}

std::vector<Eigen::Vector2d> thinned(const std::vector<Eigen::Vector2d>& pts) {
  if (pts.size() <= kMaxTracePoints) return pts;
  std::vector<Eigen::Vector2d> out;
  const double stride = static_cast<double>(pts.size()) / kMaxTracePoints;
  for (std::size_t i = 0; i < kMaxTracePoints; ++i) out.push_back(pts[static_cast<std::size_t>(i * stride)]);
  out.push_back(pts.back());
  return out;
}

// `opacity` < 1 keeps the graph in the background (under the driven queries).
void draw_edges(SvgCanvas& c, const PgcsDrawing& d, double opacity) {
  c.begin_group("legal-edges", 0.9 * opacity);
  for (const auto& [a, b] : d.legal_edges) c.line(a, b, Style{"none", kLegalEdge, 1.0});
  c.end_group();
  c.begin_group("illegal-edges", opacity);
  Style illegal{"none", kIllegalEdge, 1.8, 0.95};
  illegal.dash = "6 4";
  for (const auto& [a, b] : d.illegal_edges) c.line(a, b, illegal);
  Style suspect{"none", kIllegalEdge, 1.4, 0.7};
  suspect.dash = "2 3";
  for (const auto& [a, b] : d.suspect_edges) c.line(a, b, suspect);
  c.end_group();
}

void draw_centres(SvgCanvas& c, const PgcsDrawing& d) {
  c.begin_group("centres");
  for (const ClusterCircle& k : d.clusters) c.dot(k.centre, 2.2, Style{kCentre, "none", 0, 0.9});
  c.end_group();
}

void draw_start(SvgCanvas& c, const PgcsDrawing& d) {
  c.circle(d.start, d.robot_radius, Style{kStartColor, "#0f5c45", 1.2, 0.8});
}

}  // namespace

std::string pgcs_figure1_svg(const world::Problem& problem, const PgcsDrawing& d, const std::string& title) {
  const Eigen::AlignedBox2d bounds = bounds_2d(problem);
  const double gap = kPanelGap * bounds.sizes().x();
  // One canvas twice as wide (plus the gap): the right panel is the left one shifted, same scale.
  Eigen::AlignedBox2d both = bounds;
  both.extend(Eigen::Vector2d(bounds.max().x() + gap + bounds.sizes().x(), bounds.max().y()));
  SvgCanvas c(both, 1400, kMarginPx, kFooterPx);
  c.text_px(kMarginPx, 19, title, 15, kText, "start", true);

  c.begin_group("clusters-panel");
  draw_world(c, problem, d);
  c.begin_group("exploration", 0.5);
  c.polyline(thinned(d.explored), Style{"none", kTrace, 0.6});
  c.end_group();
  c.begin_group("clusters");
  for (const ClusterCircle& k : d.clusters) {
    c.circle(k.centre, k.sigma, Style{kClusterColor, kClusterColor, 1.0, 0.25});
  }
  c.end_group();
  draw_centres(c, d);
  draw_start(c, d);
  c.end_group();

  const double shift = (bounds.sizes().x() + gap) * c.scale();
  c.begin_shifted_group("graph-panel", shift, 0.0);
  draw_world(c, problem, d);
  draw_edges(c, d, 1.0);
  draw_centres(c, d);
  draw_start(c, d);
  c.end_group();

  char caption[160];
  std::snprintf(caption, sizeof caption, "%zu clusters after %ld steps (circles: radius sigma)", d.clusters.size(),
                d.steps);
  FigureLegend legend(c, c.height_px() - kFooterPx / 2.0, kMarginPx, kText);
  legend.item(kClusterColor, caption, 0.4);
  legend.item(kLegalEdge, "legal edges: " + std::to_string(d.legal_edges.size()));
  legend.item(kIllegalEdge, "illegal edges (dashed): " + std::to_string(d.illegal_edges.size()));
  if (!d.suspect_edges.empty()) {
    legend.item(kIllegalEdge, "blocked, not yet illegal (dotted): " + std::to_string(d.suspect_edges.size()), 0.7);
  }
  legend.item(kStartColor, "start");
  if (!d.appeared.empty()) legend.item(kAppeared, "appeared while exploring");
  return c.str();
}

std::string pgcs_queries_svg(const world::Problem& problem, const PgcsDrawing& d,
                             const std::vector<QueryDrawing>& queries, const std::string& title) {
  SvgCanvas c(bounds_2d(problem), 900, kMarginPx, kFooterPx);
  c.text_px(kMarginPx, 19, title, 15, kText, "start", true);
  draw_world(c, problem, d);
  draw_edges(c, d, 0.35);  // the graph the routes were planned on, faint
  std::size_t solved = 0, replans = 0;
  c.begin_group("queries");
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const QueryDrawing& q = queries[i];
    solved += q.solved ? 1 : 0;
    replans += static_cast<std::size_t>(q.replans);
    Style path{"none", cluster_color(static_cast<int>(i)), 2.0, 0.9, true};
    if (!q.solved) path.dash = "5 4";
    c.polyline(thinned(q.trace), path);
    c.dot(q.start, 4.0, Style{kStartColor, "#ffffff", 1.2});
    c.dot(q.target, 4.0, Style{kTargetColor, "#ffffff", 1.2});
  }
  c.end_group();
  c.begin_group("replans");
  const double h = kCrossPx / c.scale();  // pixels to world units
  const Style cross{"none", kIllegalEdge, 2.0};
  for (const QueryDrawing& q : queries) {
    for (const Eigen::Vector2d& b : q.blocks) {
      c.line(b + Eigen::Vector2d(-h, -h), b + Eigen::Vector2d(h, h), cross);
      c.line(b + Eigen::Vector2d(-h, h), b + Eigen::Vector2d(h, -h), cross);
    }
  }
  c.end_group();
  FigureLegend legend(c, c.height_px() - kFooterPx / 2.0, kMarginPx, kText);
  legend.item(kStartColor, "query start");
  legend.item(kTargetColor, "target");
  legend.item(cluster_color(0),
              "solved: " + std::to_string(solved) + " of " + std::to_string(queries.size()) + " (unsolved dashed)");
  legend.item(kIllegalEdge, "replans (x): " + std::to_string(replans));
  if (!d.appeared.empty()) legend.item(kAppeared, "appeared while exploring");
  return c.str();
}

}  // namespace amp::viz
