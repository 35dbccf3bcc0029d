#include "amp/learn/pgcs_index.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace amp::learn {

void PgcsIndex::build(std::span<const int> ids, std::span<const Eigen::Vector2d> mu, std::span<const double> s2,
                      std::span<const double> ps) {
  nodes_.clear();
  order_.assign(ids.begin(), ids.end());
  leaf_of_.assign(mu.size(), -1);
  if (order_.empty()) return;
  nodes_.reserve(4 * order_.size() / static_cast<std::size_t>(leaf_size_) + 2);
  build_node(0, static_cast<int>(order_.size()), -1, mu, s2, ps);
}

int PgcsIndex::build_node(int begin, int end, int parent, std::span<const Eigen::Vector2d> mu,
                          std::span<const double> s2, std::span<const double> ps) {
  const int n = static_cast<int>(nodes_.size());
  nodes_.push_back({});
  Node node{mu[order_[begin]].x(), mu[order_[begin]].y(), mu[order_[begin]].x(), mu[order_[begin]].y(),
            s2[order_[begin]], s2[order_[begin]], ps[order_[begin]], begin, end, -1, -1, parent};
  for (int i = begin; i < end; ++i) {
    const int k = order_[i];
    node.x0 = std::min(node.x0, mu[k].x());
    node.y0 = std::min(node.y0, mu[k].y());
    node.x1 = std::max(node.x1, mu[k].x());
    node.y1 = std::max(node.y1, mu[k].y());
    node.s_lo = std::min(node.s_lo, s2[k]);
    node.s_hi = std::max(node.s_hi, s2[k]);
    node.ps_max = std::max(node.ps_max, ps[k]);
  }
  if (end - begin <= leaf_size_) {
    for (int i = begin; i < end; ++i) leaf_of_[order_[i]] = n;
    nodes_[n] = node;
    return n;
  }
  // Median split across the wider side of the box.
  const int axis = node.x1 - node.x0 >= node.y1 - node.y0 ? 0 : 1;
  const int mid = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                   [&](int a, int b) { return mu[a][axis] < mu[b][axis] || (mu[a][axis] == mu[b][axis] && a < b); });
  node.left = build_node(begin, mid, n, mu, s2, ps);
  node.right = build_node(mid, end, n, mu, s2, ps);
  nodes_[n] = node;
  return n;
}

void PgcsIndex::touch(int id, const Eigen::Vector2d& mu, double s2, double ps) {
  for (int n = leaf_of_[id]; n >= 0; n = nodes_[n].parent) {
    Node& node = nodes_[n];
    node.x0 = std::min(node.x0, mu.x());
    node.y0 = std::min(node.y0, mu.y());
    node.x1 = std::max(node.x1, mu.x());
    node.y1 = std::max(node.y1, mu.y());
    node.s_lo = std::min(node.s_lo, s2);
    node.s_hi = std::max(node.s_hi, s2);
    node.ps_max = std::max(node.ps_max, ps);
  }
}

double PgcsIndex::lower_bound(int n, const Eigen::Vector2d& x, double log_scale) const {
  const Node& node = nodes_[n];
  const double dx = std::max({node.x0 - x.x(), 0.0, x.x() - node.x1});
  const double dy = std::max({node.y0 - x.y(), 0.0, x.y() - node.y1});
  const double d2 = dx * dx + dy * dy;
  const double s = std::clamp(0.5 * d2, node.s_lo, node.s_hi);  // argmin of d2/s + 2 log(2 pi s)
  const double bound = d2 / s + 2.0 * std::log(2.0 * std::numbers::pi * s) - 2.0 * (log_scale + std::log(node.ps_max));
  // Lowered by a few ulps' worth, so that rounding never lifts it above a member's own criterion.
  constexpr double kRoundingSlack = 1e-12;
  return bound - kRoundingSlack * (1.0 + std::abs(bound));
}

}  // namespace amp::learn
