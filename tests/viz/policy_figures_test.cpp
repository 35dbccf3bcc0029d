// The policy-search pictures on made-up phases and profiles: what each figure must show, counted in
// its SVG elements.
#include "amp/viz/policy_figures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/world/problem.hpp"
#include "support/source_tree.hpp"

namespace {

using amp::viz::PolicyPhase;
using amp::viz::PolicyPhasesDrawing;
using amp::viz::VelocityProfile;

const std::filesystem::path kOk = std::filesystem::path(AMP_SOURCE_DIR) / "tests" / "apps" / "data" / "ok.yaml";

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

PolicyPhasesDrawing three_phases() {
  PolicyPhasesDrawing d;
  d.start = {1, 1};
  d.goal = {9, 9};
  d.footprint = {0.6, 0.6, true};  // the disc of radius 0.3
  d.phases = {{"(a) cells", {{1, 1}, {2, 2}, {3, 3}, {9, 9}}, false, std::nullopt},
              {"(b) projected", {{1, 1}, {5, 5}, {9, 9}}, true, -12.5},
              {"(c) searched", {{1, 1}, {4, 6}, {9, 9}}, true, -11.25}};
  return d;
}

TEST(PolicyFigures, OnePanelPerPhaseWithItsWaypointsAndValue) {
  const amp::world::Problem problem = amp::world::load_problem(kOk);
  const std::string svg = amp::viz::policy_phases_svg(problem, three_phases(), "test");
  EXPECT_EQ(count(svg, "class=\"phase\""), 3u);
  EXPECT_EQ(count(svg, "class=\"obstacles\""), 3u);  // the map under every panel
  // Waypoints are dots (r in pixels) in (b) and (c), 3 each; the cell path of (a) has none. The
  // start and goal footprints are circles in every panel.
  EXPECT_EQ(count(svg, "<circle"), 3u * 2u + 3u + 3u);
  EXPECT_NE(svg.find("(b) projected, 3 waypoints, V = -12.50"), std::string::npos);
  EXPECT_NE(svg.find("(c) searched, 3 waypoints, V = -11.25"), std::string::npos);
  EXPECT_NE(svg.find("(a) cells"), std::string::npos);
  EXPECT_EQ(svg.find("(a) cells, "), std::string::npos);  // a cell path has no waypoint count or value
  // Panels two per row: the third starts a second row (shifted down, not right).
  EXPECT_EQ(count(svg, "transform=\"translate(0.00 "), 2u);
}

// The text between `open` and the next `close` at or after `from`.
std::string between(const std::string& text, const std::string& open, const std::string& close, std::size_t from = 0) {
  const std::size_t begin = text.find(open, from) + open.size();
  return text.substr(begin, text.find(close, begin) - begin);
}

// Each <polygon>'s corners in pixels, in order.
std::vector<std::vector<std::pair<double, double>>> polygons(const std::string& svg) {
  std::vector<std::vector<std::pair<double, double>>> out;
  const std::string open = "<polygon points=\"";
  for (auto at = svg.find(open); at != std::string::npos; at = svg.find(open, at + 1)) {
    std::vector<std::pair<double, double>> corners;
    double x = 0, y = 0;
    int used = 0;
    for (const char* p = svg.c_str() + at + open.size(); std::sscanf(p, "%lf,%lf %n", &x, &y, &used) == 2; p += used) {
      corners.emplace_back(x, y);
    }
    out.push_back(corners);
  }
  return out;
}

bool has_polygon(const std::string& svg, std::vector<std::pair<double, double>> want) {
  for (auto corners : polygons(svg)) {
    if (corners.size() != want.size()) continue;
    std::sort(corners.begin(), corners.end());
    std::sort(want.begin(), want.end());
    bool same = true;
    for (std::size_t i = 0; i < want.size(); ++i) {
      same = same && std::abs(corners[i].first - want[i].first) <= 0.011 &&
             std::abs(corners[i].second - want[i].second) <= 0.011;
    }
    if (same) return true;
  }
  return false;
}

// One waypoint panel on ok.yaml's 10 m x 10 m world: one column, 420 px wide with 28 px margins,
// so 36.4 px/m and a point (x, y) at pixel (28 + 36.4 x, 28 + 36.4 (10 - y)).
PolicyPhasesDrawing one_rectangle_panel() {
  PolicyPhasesDrawing d;
  d.start = {2, 2};
  d.goal = {8, 8};
  d.footprint = {1.0, 0.6, false};
  d.phases = {{"(b) up then right", {{2, 2}, {2, 8}, {8, 8}}, true, std::nullopt}};
  return d;
}

TEST(PolicyFigures, RectangleFootprintAtItsPoses) {
  const amp::world::Problem problem = amp::world::load_problem(kOk);
  const std::string svg = amp::viz::policy_phases_svg(problem, one_rectangle_panel(), "test");
  EXPECT_EQ(count(svg, "<circle"), 3u);  // only the waypoints' dots: the footprint is no disc
  // At the start, facing the goal (45 degrees): corners (2, 2) + 0.5 (c, c) +- 0.3 (-c, c) with
  // c = sqrt(1/2), i.e. (2.1414, 2.5657), (1.4343, 1.8586), (1.8586, 1.4343), (2.5657, 2.1414).
  EXPECT_TRUE(has_polygon(svg, {{105.95, 298.61}, {80.21, 324.35}, {95.65, 339.79}, {121.39, 314.05}}));
  // At the goal, along the last segment (east): x in 8 -+ 0.5, y in 8 -+ 0.3.
  EXPECT_TRUE(has_polygon(svg, {{301.0, 89.88}, {337.4, 89.88}, {337.4, 111.72}, {301.0, 111.72}}));
  // Outlined at the two waypoints that begin a segment: (2, 2) facing north, (2, 8) facing east.
  EXPECT_TRUE(has_polygon(svg, {{89.88, 301.0}, {89.88, 337.4}, {111.72, 337.4}, {111.72, 301.0}}));
  EXPECT_TRUE(has_polygon(svg, {{82.6, 89.88}, {119.0, 89.88}, {119.0, 111.72}, {82.6, 111.72}}));
  EXPECT_EQ(count(between(svg, "class=\"waypoint-footprints\"", "</g>"), "<polygon"), 2u);
  EXPECT_EQ(count(between(svg, "class=\"ends\"", "</g>"), "<polygon"), 2u);
}

TEST(PolicyFigures, DrivenTraceOnTheLastPanelOnly) {
  const amp::world::Problem problem = amp::world::load_problem(kOk);
  PolicyPhasesDrawing d = three_phases();
  d.trace = {{1, 1}, {2, 1.5}, {3, 2}, {3.5, 2.5}};
  std::string svg = amp::viz::policy_phases_svg(problem, d, "test");
  ASSERT_EQ(count(svg, "class=\"driven\""), 1u);
  EXPECT_GT(svg.find("class=\"driven\""), svg.rfind("class=\"phase\""));  // inside the last panel
  const std::string pts = between(svg, "points=\"", "\"", svg.find("class=\"driven\""));
  EXPECT_EQ(count(pts, ","), 4u);  // one point per trace position
  EXPECT_NE(svg.find("driven (first seed)"), std::string::npos);
  EXPECT_EQ(svg.find("stopped"), std::string::npos);  // arrived: no cross
  d.arrived = false;
  svg = amp::viz::policy_phases_svg(problem, d, "test");
  EXPECT_EQ(count(between(svg, "class=\"stopped\"", "</g>"), "<line"), 2u);  // a cross at the trace's end
  EXPECT_NE(svg.find(">stopped<"), std::string::npos);
}

TEST(PolicyFigures, LongCaptionsStayWithinTheirPanel) {
  const amp::world::Problem problem = amp::world::load_problem(kOk);
  PolicyPhasesDrawing d = three_phases();
  std::vector<Eigen::Vector2d> many(18, Eigen::Vector2d(5, 5));
  d.phases.push_back({"(d) after insertions, passages squared", many, true, -200.89});
  const std::string svg = amp::viz::policy_phases_svg(problem, d, "test");
  const double panel = std::stod(between(svg, "width=\"", "\"", svg.find("class=\"workspace\"")));
  std::vector<std::pair<std::string, double>> texts;  // each <text>'s content and font size
  for (auto at = svg.find("<text"); at != std::string::npos; at = svg.find("<text", at + 1)) {
    texts.emplace_back(between(svg, ">", "</text>", at), std::stod(between(svg, "font-size=\"", "\"", at)));
  }
  std::vector<std::pair<std::string, double>> captions;  // the (a) to (d) lines, and (d)'s second one
  for (std::size_t i = 0; i < texts.size(); ++i) {
    if (texts[i].first.rfind("(", 0) == 0) captions.push_back(texts[i]);
    if (texts[i].first.rfind("(d)", 0) == 0 && i + 1 < texts.size()) captions.push_back(texts[i + 1]);
  }
  ASSERT_EQ(captions.size(), 5u);
  // Each line, at the font size it is drawn with, is estimated no wider than the panel at 0.6 em
  // per character: above the average advance of Helvetica/Arial (about 0.5 em on such text, as
  // rsvg draws it) and of DejaVu Sans, the usual fallback.
  for (const auto& [line, size] : captions) {
    EXPECT_LE(0.6 * size * static_cast<double>(line.size()), panel) << line;
    EXPECT_GE(size, 9.0) << line;
  }
  const std::string last = captions[3].first + " " + captions[4].first;
  // The long caption is wrapped after a comma, whole, at the usual size.
  EXPECT_EQ(last, "(d) after insertions, passages squared, 18 waypoints, V = -200.89");
  EXPECT_NE(svg.find(">(d) after insertions, passages squared,</text>"), std::string::npos);
  EXPECT_EQ(captions[3].second, 13.0);
  EXPECT_EQ(captions[4].second, 13.0);
  // Far too long even for two lines: smaller, then cut, never wider than the panel.
  PolicyPhasesDrawing huge = three_phases();
  huge.phases.resize(1);
  huge.phases[0].name = "(a) " + std::string(60, 'w') + " " + std::string(60, 'w') + " " + std::string(60, 'w');
  const std::string cut = amp::viz::policy_phases_svg(problem, huge, "test");
  const double one_panel = std::stod(between(cut, "width=\"", "\"", cut.find("class=\"workspace\"")));
  for (auto at = cut.find("<text"); at != std::string::npos; at = cut.find("<text", at + 1)) {
    const std::string line = between(cut, ">", "</text>", at);
    if (line.find("www") == std::string::npos) continue;
    const double size = std::stod(between(cut, "font-size=\"", "\"", at));
    EXPECT_LE(0.6 * size * static_cast<double>(line.size()), one_panel) << line;
    EXPECT_GE(size, 9.0) << line;
  }
  EXPECT_NE(cut.find("...</text>"), std::string::npos);
}

TEST(PolicyFigures, VelocityProfilesOneLinePerMethodFromRest) {
  const std::string svg = amp::viz::velocity_profiles_svg(
      {{"policy search", {0.1, 0.2, 0.25}}, {"DWA", {0.05, 0.1}}}, 0.5, "speeds");
  EXPECT_EQ(count(svg, "class=\"profile\""), 2u);
  EXPECT_NE(svg.find("policy search"), std::string::npos);
  EXPECT_NE(svg.find("DWA"), std::string::npos);
  EXPECT_NE(svg.find("time (s)"), std::string::npos);
  // Each line has a point at rest (t = 0) and one per step.
  const auto points_of = [&](std::size_t nth) {
    std::size_t at = 0;
    for (std::size_t i = 0; i <= nth; ++i) at = svg.find("class=\"profile\"", at + 1);
    const auto begin = svg.find("points=\"", at) + 8;
    const std::string pts = svg.substr(begin, svg.find('"', begin) - begin);
    return count(pts, ",");
  };
  EXPECT_EQ(points_of(0), 4u);
  EXPECT_EQ(points_of(1), 3u);
  EXPECT_THROW(amp::viz::velocity_profiles_svg({}, 0.0, "x"), amp::ParameterError);
}

}  // namespace
