#include "amp/learn/silhouette.hpp"

#include <algorithm>
#include <cstddef>
#include <limits>

namespace amp::learn {

double mean_silhouette(const Eigen::MatrixXd& points, const std::vector<int>& labels, int c,
                       const core::StopCondition* stop) {
  const Eigen::Index n = points.rows();
  if (c < 2 || n < 2) return 0.0;
  std::vector<double> size(static_cast<std::size_t>(c), 0.0);
  for (const int l : labels) size[static_cast<std::size_t>(l)] += 1.0;
  std::vector<double> sum(static_cast<std::size_t>(c));  // distance sums from point i to each cluster
  double total = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    poll(stop);
    std::fill(sum.begin(), sum.end(), 0.0);
    for (Eigen::Index j = 0; j < n; ++j) {
      if (j != i) sum[static_cast<std::size_t>(labels[static_cast<std::size_t>(j)])] += (points.row(i) - points.row(j)).norm();
    }
    const auto own = static_cast<std::size_t>(labels[static_cast<std::size_t>(i)]);
    if (size[own] < 2.0) continue;  // a singleton: s(i) = 0
    const double a = sum[own] / (size[own] - 1.0);
    double b = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < sum.size(); ++k) {
      if (k != own && size[k] > 0.0) b = std::min(b, sum[k] / size[k]);
    }
    const double m = std::max(a, b);
    if (m > 0.0) total += (b - a) / m;
  }
  return total / static_cast<double>(n);
}

}  // namespace amp::learn
