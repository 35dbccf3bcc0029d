#include "amp/learn/standardize.hpp"

#include <algorithm>
#include <cmath>

namespace amp::learn {
namespace {

constexpr double kConstantColumn = 1e-12;  // sd below this fraction of the column's scale: constant

}  // namespace

Eigen::MatrixXd standardize(const Eigen::MatrixXd& points) {
  const Eigen::Index n = points.rows();
  Eigen::MatrixXd z = Eigen::MatrixXd::Zero(n, points.cols());
  if (n < 2) return z;
  for (Eigen::Index j = 0; j < points.cols(); ++j) {
    const double mean = points.col(j).mean();
    const Eigen::ArrayXd centred = points.col(j).array() - mean;
    const double sd = std::sqrt(centred.square().sum() / static_cast<double>(n - 1));
    const double scale = std::max(std::abs(mean), points.col(j).cwiseAbs().maxCoeff());
    if (sd > kConstantColumn * scale) z.col(j) = centred / sd;
  }
  return z;
}

}  // namespace amp::learn
