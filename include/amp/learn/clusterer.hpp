#pragma once
#include <stdexcept>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "amp/core/rng.hpp"
#include "amp/core/stop_condition.hpp"

namespace amp::learn {

// The result of clustering n points of dimension d.
struct Clustering {
  std::vector<int> labels;  // size n, values 0..c-1, numbered in order of first appearance
  Eigen::MatrixXd centres;  // c x d, row j = centre of cluster j
  int c = 0;
  // The score the method chose c by: curve[i] belongs to c = i + 1. k-means and Ward: the
  // explained-variance curve W(c)/T (see elbow.hpp); PG-means: for each k it fitted, the largest
  // KS statistic over the projections divided by the critical value (accepted when <= 1).
  std::vector<double> curve;
};

// Thrown out of a clustering when the stop condition it was given fires: a clustering is all or
// nothing, so a planner that clusters inside its run (UAS) ends the run as stopped.
class ClusteringStopped : public std::runtime_error {
 public:
  ClusteringStopped() : std::runtime_error("clustering stopped by the run's stop condition") {}
};

// Between two steps of a clustering: throws ClusteringStopped once `stop` (null: never) has fired.
inline void poll(const core::StopCondition* stop) {
  if (stop != nullptr && stop->time_up()) throw ClusteringStopped();
}

// Partitions points (rows of an n x d matrix) into clusters whose number the method chooses itself.
// Implementations: KMeans, WardClustering, PgMeans, AutoClusterer. Same input and same Rng state,
// same result.
class Clusterer {
 public:
  virtual ~Clusterer() = default;
  Clustering cluster(const Eigen::MatrixXd& points, core::Rng& rng) const { return cluster(points, rng, nullptr); }
  // Polls `stop` between steps (each a pass over the points at most) and throws ClusteringStopped
  // when it fires, so that a run's time limit holds through an O(n^2) clustering.
  virtual Clustering cluster(const Eigen::MatrixXd& points, core::Rng& rng, const core::StopCondition* stop) const = 0;
  virtual std::string_view name() const = 0;
};

// Throws ParameterError unless points has at least one row, one column and only finite values;
// `who` names the caller in the message.
void validate_points(const Eigen::MatrixXd& points, std::string_view who);

// Centres (c x d) as the means of the labelled points; an empty cluster's row is left at zero.
Eigen::MatrixXd cluster_means(const Eigen::MatrixXd& points, const std::vector<int>& labels, int c);

// Renumbers labels 0.. in order of first appearance and drops empty clusters, permuting the rows of
// centres to match; returns the number of clusters left. Makes results comparable across methods
// and independent of the internal numbering.
int canonicalise(std::vector<int>& labels, Eigen::MatrixXd& centres);

}  // namespace amp::learn
