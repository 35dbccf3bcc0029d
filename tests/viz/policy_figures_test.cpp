// The policy-search pictures on made-up phases and profiles: what each figure must show, counted in
// its SVG elements.
#include "amp/viz/policy_figures.hpp"

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/world/problem.hpp"

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
  d.robot_radius = 0.3;
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
