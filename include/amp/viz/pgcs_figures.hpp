#pragma once
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "amp/world/problem.hpp"
#include "amp/world/shapes2d.hpp"

namespace amp::viz {

// The pictures of a PGCS exploration (Vlassis, Papakonstantinou & Tsanakas, "Learning the Voronoi
// centers of a mobile robot's configuration space"). They take plain values, not the session, so
// viz stays below nav in the module graph and a test can draw made-up clusters; the app converts.

// One cluster: its centre and sigma (the square root of its variance).
struct ClusterCircle {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double sigma = 0.0;
};

using Segment2 = std::pair<Eigen::Vector2d, Eigen::Vector2d>;

// What the exploration learned, as drawn.
struct PgcsDrawing {
  std::vector<ClusterCircle> clusters;
  std::vector<Segment2> legal_edges;    // graph edges not known to be blocked
  std::vector<Segment2> illegal_edges;  // blocked ones, at the places their ends had when found
  std::vector<Segment2> suspect_edges;  // blocked fewer times than make an edge illegal
  std::vector<Eigen::Vector2d> explored;  // the exploration's trace (thinned)
  // Obstacles that appeared while exploring (a door that closed), drawn over the map, which shows
  // the world as loaded.
  std::vector<world::Shapes2d> appeared;
  Eigen::Vector2d start = Eigen::Vector2d::Zero();  // where exploration began
  double robot_radius = 0.0;
  long steps = 0;
};

// One sample of the curves over the exploration.
struct CurveSample {
  long step = 0;
  int clusters = 0;
  double coverage = 0.0;
  double quantisation_error = 0.0;
  double closed_prior = 0.0;
};

// One query as driven.
struct QueryDrawing {
  Eigen::Vector2d start = Eigen::Vector2d::Zero(), target = Eigen::Vector2d::Zero();
  bool solved = false;
  int replans = 0;
  std::vector<Eigen::Vector2d> trace;   // driven positions
  std::vector<Eigen::Vector2d> blocks;  // where the robot stopped and replanned
};

// The paper's Figure 1: left, the clusters as circles of radius sigma over the map; right, the same
// map with the centres' Delaunay graph, legal edges grey and illegal ones red and dashed.
// Only the world's 2-D outline is drawn (3-D problems are not PGCS problems).
std::string pgcs_figure1_svg(const world::Problem& problem, const PgcsDrawing& drawing, const std::string& title);

// Clusters, coverage and quantisation error against steps, one panel each sharing the step axis;
// a fourth panel for closed_prior when any sample has it non-zero.
std::string pgcs_curves_svg(const std::vector<CurveSample>& curves, const std::string& title);

// The driven paths over the map and the learned graph, one colour per query, replans as red
// crosses, unsolved queries dashed.
std::string pgcs_queries_svg(const world::Problem& problem, const PgcsDrawing& drawing,
                             const std::vector<QueryDrawing>& queries, const std::string& title);

}  // namespace amp::viz
