#include "amp/learn/clusterer.hpp"

#include <cmath>
#include <cstddef>
#include <string>
#include <utility>

#include "amp/core/error.hpp"

namespace amp::learn {

void validate_points(const Eigen::MatrixXd& points, std::string_view who) {
  if (points.rows() == 0 || points.cols() == 0) {
    throw ParameterError(std::string(who) + ": points: empty matrix (" + std::to_string(points.rows()) +
                         " x " + std::to_string(points.cols()) + ")");
  }
  if (!points.allFinite()) {
    throw ParameterError(std::string(who) + ": points: contains a non-finite value");
  }
}

Eigen::MatrixXd cluster_means(const Eigen::MatrixXd& points, const std::vector<int>& labels, int c) {
  Eigen::MatrixXd centres = Eigen::MatrixXd::Zero(c, points.cols());
  Eigen::VectorXd counts = Eigen::VectorXd::Zero(c);
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const int l = labels[static_cast<std::size_t>(i)];
    centres.row(l) += points.row(i);
    counts[l] += 1.0;
  }
  for (int j = 0; j < c; ++j) {
    if (counts[j] > 0.0) centres.row(j) /= counts[j];
  }
  return centres;
}

int canonicalise(std::vector<int>& labels, Eigen::MatrixXd& centres) {
  std::vector<int> renumber(static_cast<std::size_t>(centres.rows()), -1);
  int next = 0;
  for (int& l : labels) {
    int& r = renumber[static_cast<std::size_t>(l)];
    if (r < 0) r = next++;
    l = r;
  }
  Eigen::MatrixXd kept(next, centres.cols());
  for (std::size_t old = 0; old < renumber.size(); ++old) {
    if (renumber[old] >= 0) kept.row(renumber[old]) = centres.row(static_cast<Eigen::Index>(old));
  }
  centres = std::move(kept);
  return next;
}

}  // namespace amp::learn
