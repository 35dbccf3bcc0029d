#include "amp/learn/elbow.hpp"

#include <cstddef>

namespace amp::learn {

int elbow_choice(std::span<const double> curve) {
  int best = 1;
  double best_d2 = 0.0;  // an elbow needs strictly positive curvature
  for (std::size_t i = 1; i + 1 < curve.size(); ++i) {
    const double d2 = curve[i - 1] - 2.0 * curve[i] + curve[i + 1];
    if (d2 > best_d2) {  // strict: ties keep the smaller c
      best_d2 = d2;
      best = static_cast<int>(i) + 1;
    }
  }
  return best;
}

double total_sum_of_squares(const Eigen::MatrixXd& points) {
  if (points.rows() == 0) return 0.0;
  const Eigen::RowVectorXd mean = points.colwise().mean();
  return (points.rowwise() - mean).squaredNorm();
}

double within_sum_of_squares(const Eigen::MatrixXd& points, const std::vector<int>& labels,
                             const Eigen::MatrixXd& centres) {
  double w = 0.0;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    w += (points.row(i) - centres.row(labels[static_cast<std::size_t>(i)])).squaredNorm();
  }
  return w;
}

}  // namespace amp::learn
