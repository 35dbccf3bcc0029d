#pragma once
#include <span>
#include <vector>

#include <Eigen/Core>

namespace amp::learn {

// A bounding-box tree over the PGCS cluster centres that finds the winner of
// c_k(x) = |x - mu_k|^2 / s2_k + 2 log(2 pi s2_k) - 2 log pi_k exactly without scanning every
// cluster, and visits the clusters whose term pi_k p_k(x) = exp(-c_k / 2) of eq. (2)'s denominator
// is not negligible.
//
// Bound of a node (Vlassis, Papakonstantinou & Tsanakas, section 3's winner criterion): with d2 the
// squared distance from x to the node's box (<= |x - mu_k|^2 for every member), s2 in [s_lo, s_hi]
// and pi_k <= pi_max for every member, c_k >= min over s in [s_lo, s_hi] of d2 / s + 2 log(2 pi s)
// - 2 log pi_max, since c_k increases with |x - mu_k|^2 and decreases with pi_k. The function
// g(s) = d2 / s + 2 log(2 pi s) has g'(s) = (2 s - d2) / s^2: it falls until s = d2 / 2 and rises
// after, so its minimum on the interval is at s = clamp(d2 / 2, s_lo, s_hi).
//
// Priors are given as stored values ps_k with pi_k = scale * ps_k (the lazy scale of Pgcs). The tree
// is refitted by touch() (boxes, variance ranges and the largest stored prior only grow, so every
// bound stays valid) and rebuilt from scratch by build() when clusters are inserted or deleted.
class PgcsIndex {
 public:
  explicit PgcsIndex(int leaf_size = 8) : leaf_size_(leaf_size) {}

  // mu, s2 and ps are indexed by cluster id; `ids` lists the live ones.
  void build(std::span<const int> ids, std::span<const Eigen::Vector2d> mu, std::span<const double> s2,
             std::span<const double> ps);
  // Cluster `id` changed (centre, variance or stored prior): widen its ancestors to hold it.
  void touch(int id, const Eigen::Vector2d& mu, double s2, double ps);
  bool empty() const { return nodes_.empty(); }

  // The lower bound of c over node n, for `log_scale` = log(scale).
  double lower_bound(int n, const Eigen::Vector2d& x, double log_scale) const;

  // Calls visit(id) for the members of every leaf whose bound is below `limit(best so far)`:
  // depth-first, the child of lower bound first. `visit` returns the new limit.
  template <class Visit>
  void search(const Eigen::Vector2d& x, double log_scale, double limit, Visit&& visit) const;

 private:
  struct Node {
    double x0, y0, x1, y1;  // box of the members' centres
    double s_lo, s_hi;      // range of their variances
    double ps_max;          // largest stored prior
    int begin, end;         // members: order_[begin, end)
    int left = -1, right = -1, parent = -1;
  };
  int build_node(int begin, int end, int parent, std::span<const Eigen::Vector2d> mu, std::span<const double> s2,
                 std::span<const double> ps);

  int leaf_size_;
  std::vector<Node> nodes_;
  std::vector<int> order_;    // cluster ids, grouped by leaf
  std::vector<int> leaf_of_;  // by cluster id
};

template <class Visit>
void PgcsIndex::search(const Eigen::Vector2d& x, double log_scale, double limit, Visit&& visit) const {
  if (nodes_.empty()) return;
  constexpr int kMaxDepth = 128;  // median splits: depth ~ log2(K / leaf size)
  int stack[kMaxDepth];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const int n = stack[--top];
    if (lower_bound(n, x, log_scale) > limit) continue;
    const Node& node = nodes_[n];
    if (node.left < 0) {
      for (int i = node.begin; i < node.end; ++i) limit = visit(order_[i]);
      continue;
    }
    const double bl = lower_bound(node.left, x, log_scale), br = lower_bound(node.right, x, log_scale);
    // Pushed last, popped first: the child of lower bound.
    stack[top++] = bl <= br ? node.right : node.left;
    stack[top++] = bl <= br ? node.left : node.right;
  }
}

}  // namespace amp::learn
