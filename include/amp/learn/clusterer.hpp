#pragma once
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "amp/core/rng.hpp"

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

// Partitions points (rows of an n x d matrix) into clusters whose number the method chooses itself.
// Implementations: KMeans, WardClustering, PgMeans. Same input and same Rng state, same result.
class Clusterer {
 public:
  virtual ~Clusterer() = default;
  virtual Clustering cluster(const Eigen::MatrixXd& points, core::Rng& rng) const = 0;
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
