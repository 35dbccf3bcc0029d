// The PGCS pictures on made-up clusters: what each figure must show, counted in its SVG elements.
#include "amp/viz/pgcs_figures.hpp"

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "amp/world/problem.hpp"
#include "support/source_tree.hpp"

namespace {

using amp::viz::ClusterCircle;
using amp::viz::CurveSample;
using amp::viz::PgcsDrawing;
using amp::viz::QueryDrawing;

const std::filesystem::path kOk = std::filesystem::path(AMP_SOURCE_DIR) / "tests" / "apps" / "data" / "ok.yaml";

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// The part of an SVG between the opening of group `name` and the next group's opening or end.
std::string group(const std::string& svg, const std::string& name) {
  const auto begin = svg.find("<g class=\"" + name + "\"");
  if (begin == std::string::npos) return {};
  const auto end = svg.find("</g>", begin);
  return svg.substr(begin, end - begin);
}

PgcsDrawing three_clusters() {
  PgcsDrawing d;
  d.clusters = {{{2, 2}, 0.5}, {{8, 2}, 0.7}, {{5, 8}, 0.4}};
  d.legal_edges = {{{2, 2}, {8, 2}}, {{2, 2}, {5, 8}}};
  d.illegal_edges = {{{8, 2}, {5, 8}}};
  d.explored = {{1, 1}, {2, 2}, {3, 2}};
  d.start = {1, 1};
  d.robot_radius = 0.3;
  d.steps = 1000;
  return d;
}

TEST(PgcsFigures, Figure1DrawsCirclesBesideTheGraph) {
  const amp::world::Problem problem = amp::world::load_problem(kOk);
  const std::string svg = amp::viz::pgcs_figure1_svg(problem, three_clusters(), "test");
  EXPECT_EQ(count(group(svg, "clusters"), "<circle"), 3u);
  EXPECT_EQ(count(group(svg, "legal-edges"), "<line"), 2u);
  const std::string illegal = group(svg, "illegal-edges");
  EXPECT_EQ(count(illegal, "<line"), 1u);
  EXPECT_NE(illegal.find("stroke-dasharray"), std::string::npos);
  EXPECT_NE(svg.find("class=\"graph-panel\" transform=\"translate("), std::string::npos);
  EXPECT_EQ(count(svg, "class=\"obstacles\""), 2u);  // the map under both panels
  EXPECT_EQ(svg.find("not yet illegal"), std::string::npos);  // no suspects: no legend line for them
}

TEST(PgcsFigures, SuspectEdgesAreDottedBesideTheIllegalOnes) {
  const amp::world::Problem problem = amp::world::load_problem(kOk);
  PgcsDrawing d = three_clusters();
  d.suspect_edges = {{{2, 2}, {5, 8}}};
  const std::string svg = amp::viz::pgcs_figure1_svg(problem, d, "test");
  const std::string blocked = group(svg, "illegal-edges");
  EXPECT_EQ(count(blocked, "<line"), 2u);
  EXPECT_NE(blocked.find("stroke-dasharray=\"6 4\""), std::string::npos);
  EXPECT_NE(blocked.find("stroke-dasharray=\"2 3\""), std::string::npos);
  EXPECT_NE(svg.find("blocked, not yet illegal (dotted): 1"), std::string::npos);
}

TEST(PgcsFigures, CurvesShowClosedPriorOnlyWhenADoorClosed) {
  std::vector<CurveSample> curves = {{0, 1, 0.0, 3.0, 0.0}, {500, 4, 0.4, 1.5, 0.0}, {1000, 7, 0.7, 0.9, 0.0}};
  const std::string open = amp::viz::pgcs_curves_svg(curves, "open");
  EXPECT_EQ(count(open, "<polyline"), 3u);
  EXPECT_EQ(open.find("closed prior"), std::string::npos);
  curves.back().closed_prior = 0.2;
  const std::string closed = amp::viz::pgcs_curves_svg(curves, "closed");
  EXPECT_EQ(count(closed, "<polyline"), 4u);
  EXPECT_NE(closed.find("closed prior"), std::string::npos);
  EXPECT_EQ(amp::viz::pgcs_curves_svg({}, "empty").find("nan"), std::string::npos);
}

TEST(PgcsFigures, QueriesMarkReplansAndDashUnsolved) {
  const amp::world::Problem problem = amp::world::load_problem(kOk);
  QueryDrawing solved{{1, 1}, {9, 9}, true, 1, {{1, 1}, {3, 3}, {9, 9}}, {{3, 3}}};
  QueryDrawing unsolved{{1, 9}, {9, 1}, false, 0, {{1, 9}, {2, 8}}, {}};
  const std::string svg = amp::viz::pgcs_queries_svg(problem, three_clusters(), {solved, unsolved}, "q");
  const std::string paths = group(svg, "queries");
  EXPECT_EQ(count(paths, "<polyline"), 2u);
  EXPECT_EQ(count(paths, "stroke-dasharray"), 1u);
  EXPECT_EQ(count(group(svg, "replans"), "<line"), 2u);  // one cross
}

}  // namespace
