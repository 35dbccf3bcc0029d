#pragma once
#include <vector>

#include <Eigen/Core>

#include "amp/learn/clusterer.hpp"

namespace amp::learn {

// Mean silhouette width (Rousseeuw 1987) of a labelling of the rows of `points` (Euclidean):
// s(i) = (b - a) / max(a, b), a = mean distance from i to the rest of its cluster, b = the smallest
// mean distance from i to another cluster; s(i) = 0 for a point alone in its cluster. In [-1, 1];
// high when clusters are compact and apart. One cluster (or none): 0, the value of "no structure".
// O(n^2 d) time, O(n c) memory. Labels must be in 0..c-1.
// `stop` is polled per point (see Clusterer::cluster).
double mean_silhouette(const Eigen::MatrixXd& points, const std::vector<int>& labels, int c,
                       const core::StopCondition* stop = nullptr);

}  // namespace amp::learn
