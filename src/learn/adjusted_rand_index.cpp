#include "amp/learn/adjusted_rand_index.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "amp/core/error.hpp"

namespace amp::learn {
namespace {

double pairs(double m) { return 0.5 * m * (m - 1.0); }

}  // namespace

double adjusted_rand_index(std::span<const int> a, std::span<const int> b) {
  if (a.size() != b.size()) {
    throw ParameterError("adjusted_rand_index: labels: lengths differ (" + std::to_string(a.size()) + " vs " +
                         std::to_string(b.size()) + ")");
  }
  if (a.size() < 2) return 1.0;  // no pairs: nothing to disagree on
  const int ka = *std::max_element(a.begin(), a.end()) + 1;
  const int kb = *std::max_element(b.begin(), b.end()) + 1;
  if (*std::min_element(a.begin(), a.end()) < 0 || *std::min_element(b.begin(), b.end()) < 0) {
    throw ParameterError("adjusted_rand_index: labels: negative label");
  }
  std::vector<double> table(static_cast<std::size_t>(ka) * static_cast<std::size_t>(kb), 0.0);
  std::vector<double> row(static_cast<std::size_t>(ka), 0.0);
  std::vector<double> col(static_cast<std::size_t>(kb), 0.0);
  for (std::size_t i = 0; i < a.size(); ++i) {
    table[static_cast<std::size_t>(a[i]) * static_cast<std::size_t>(kb) + static_cast<std::size_t>(b[i])] += 1.0;
    row[static_cast<std::size_t>(a[i])] += 1.0;
    col[static_cast<std::size_t>(b[i])] += 1.0;
  }
  double index = 0.0;
  for (double t : table) index += pairs(t);
  double sum_a = 0.0;
  for (double r : row) sum_a += pairs(r);
  double sum_b = 0.0;
  for (double c : col) sum_b += pairs(c);
  const double expected = sum_a * sum_b / pairs(static_cast<double>(a.size()));
  const double max_index = 0.5 * (sum_a + sum_b);
  if (max_index == expected) return 1.0;
  return (index - expected) / (max_index - expected);
}

}  // namespace amp::learn
