#include "amp/learn/ward.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "amp/core/error.hpp"
#include "amp/learn/elbow.hpp"

namespace amp::learn {
namespace {

// Union-find over point indices, used to turn merges of representative points into cluster ids.
class UnionFind {
 public:
  explicit UnionFind(int n) : parent_(static_cast<std::size_t>(n)) { std::iota(parent_.begin(), parent_.end(), 0); }
  int find(int x) {
    while (parent_[static_cast<std::size_t>(x)] != x) {
      int& p = parent_[static_cast<std::size_t>(x)];
      p = parent_[static_cast<std::size_t>(p)];  // path halving
      x = p;
    }
    return x;
  }
  int unite(int a, int b) {  // returns the new root
    a = find(a);
    b = find(b);
    parent_[static_cast<std::size_t>(b)] = a;
    return a;
  }

 private:
  std::vector<int> parent_;
};

// A merge found by the chain: slots are point indices standing for their clusters.
struct RawMerge {
  int slot_a;
  int slot_b;
  double height;
};

}  // namespace

std::vector<int> WardDendrogram::cut(int c) const {
  if (c < 1 || c > n) throw ParameterError("ward: cut: c = " + std::to_string(c) + " outside 1.." + std::to_string(n));
  UnionFind uf(n);
  // Merge i joins clusters a and b; track one member point of every cluster id.
  std::vector<int> member(static_cast<std::size_t>(2 * n));
  std::iota(member.begin(), member.begin() + n, 0);
  for (int i = 0; i < n - c; ++i) {
    const WardMerge& m = merges[static_cast<std::size_t>(i)];
    member[static_cast<std::size_t>(n + i)] =
        uf.unite(member[static_cast<std::size_t>(m.a)], member[static_cast<std::size_t>(m.b)]);
  }
  std::vector<int> root_label(static_cast<std::size_t>(n), -1);
  std::vector<int> labels(static_cast<std::size_t>(n));
  int next = 0;
  for (int i = 0; i < n; ++i) {
    int& l = root_label[static_cast<std::size_t>(uf.find(i))];
    if (l < 0) l = next++;
    labels[static_cast<std::size_t>(i)] = l;
  }
  return labels;
}

namespace {

// Squared Ward distances between the clusters in slots i and j, initially |xi - xj|^2; a merged
// cluster lives on in one of its two slots.
class WardDistances {
 public:
  WardDistances(const Eigen::MatrixXd& points, const core::StopCondition* stop)
      : n_(static_cast<std::size_t>(points.rows())), d2_(n_ * n_, 0.0) {
    const int n = static_cast<int>(n_);
    for (int i = 0; i < n; ++i) {
      poll(stop);
      for (int j = i + 1; j < n; ++j) {
        const double d = (points.row(i) - points.row(j)).squaredNorm();
        at(i, j) = d;
        at(j, i) = d;
      }
    }
  }
  double& at(int i, int j) { return d2_[static_cast<std::size_t>(i) * n_ + static_cast<std::size_t>(j)]; }

 private:
  std::size_t n_;
  std::vector<double> d2_;
};

// The active slots, each cluster's size, and the distances between them as merges go on.
struct WardSlots {
  WardDistances d;
  std::vector<int> size;
  std::vector<char> active;
  int n;
};

// Grows the nearest-neighbour chain until its last two clusters are each other's nearest.
void grow_chain(WardSlots& w, std::vector<int>& chain) {
  for (;;) {
    const int a = chain.back();
    const int prev = chain.size() >= 2 ? chain[chain.size() - 2] : -1;
    int b = prev;  // prefer the previous element on ties, which guarantees termination
    double best = prev >= 0 ? w.d.at(a, prev) : std::numeric_limits<double>::infinity();
    for (int j = 0; j < w.n; ++j) {
      if (j == a || !w.active[static_cast<std::size_t>(j)]) continue;
      if (w.d.at(a, j) < best) {
        best = w.d.at(a, j);
        b = j;
      }
    }
    if (b == prev) return;
    chain.push_back(b);
  }
}

// Merges the clusters in slots a and b at Ward distance^2 dab.
void merge_slots(WardSlots& w, int a, int b, double dab) {
  // The merged cluster lives in slot lo; hi is retired. Lance-Williams update for Ward on squared
  // distances: d(k, a+b) = ((na+nk) d(k,a) + (nb+nk) d(k,b) - nk d(a,b)) / (na+nb+nk).
  const int lo = std::min(a, b);
  const int hi = std::max(a, b);
  const double na = w.size[static_cast<std::size_t>(a)];
  const double nb = w.size[static_cast<std::size_t>(b)];
  for (int k = 0; k < w.n; ++k) {
    if (!w.active[static_cast<std::size_t>(k)] || k == a || k == b) continue;
    const double nk = w.size[static_cast<std::size_t>(k)];
    const double d = ((na + nk) * w.d.at(k, a) + (nb + nk) * w.d.at(k, b) - nk * dab) / (na + nb + nk);
    w.d.at(k, lo) = d;
    w.d.at(lo, k) = d;
  }
  w.size[static_cast<std::size_t>(lo)] += w.size[static_cast<std::size_t>(hi)];
  w.active[static_cast<std::size_t>(hi)] = 0;
}

// The n - 1 merges in the order the nearest-neighbour chain finds them.
std::vector<RawMerge> chain_merges(WardSlots& w, const core::StopCondition* stop) {
  const auto un = static_cast<std::size_t>(w.n);
  std::vector<int> chain;
  chain.reserve(un);
  std::vector<RawMerge> raw;
  raw.reserve(un);
  int first_active = 0;
  while (static_cast<int>(raw.size()) < w.n - 1) {
    poll(stop);  // each merge costs O(n) per chain step
    if (chain.empty()) {
      while (!w.active[static_cast<std::size_t>(first_active)]) ++first_active;
      chain.push_back(first_active);
    }
    grow_chain(w, chain);
    const int a = chain.back();
    chain.pop_back();
    const int b = chain.back();
    chain.pop_back();
    const double dab = w.d.at(a, b);
    raw.push_back({a, b, std::sqrt(dab)});
    merge_slots(w, a, b, dab);
  }
  return raw;
}

// Sorts the merges by height (stable, so equal heights keep the chain's order) and names clusters
// as SciPy does: point i is cluster i, merge i makes cluster n + i.
WardDendrogram scipy_dendrogram(std::vector<RawMerge> raw, int n) {
  std::stable_sort(raw.begin(), raw.end(), [](const RawMerge& x, const RawMerge& y) { return x.height < y.height; });
  const auto un = static_cast<std::size_t>(n);
  WardDendrogram out;
  out.n = n;
  out.merges.reserve(raw.size());
  UnionFind uf(n);
  std::vector<int> id(un);  // cluster id of each union-find root
  std::iota(id.begin(), id.end(), 0);
  std::vector<int> cluster_size(un, 1);
  for (std::size_t i = 0; i < raw.size(); ++i) {
    const int ra = uf.find(raw[i].slot_a);
    const int rb = uf.find(raw[i].slot_b);
    const int ia = id[static_cast<std::size_t>(ra)];
    const int ib = id[static_cast<std::size_t>(rb)];
    const int sz = cluster_size[static_cast<std::size_t>(ra)] + cluster_size[static_cast<std::size_t>(rb)];
    out.merges.push_back({std::min(ia, ib), std::max(ia, ib), raw[i].height, sz});
    const int root = uf.unite(ra, rb);
    id[static_cast<std::size_t>(root)] = n + static_cast<int>(i);
    cluster_size[static_cast<std::size_t>(root)] = sz;
  }
  return out;
}

}  // namespace

WardDendrogram ward_linkage(const Eigen::MatrixXd& points, const core::StopCondition* stop) {
  validate_points(points, "ward");
  const int n = static_cast<int>(points.rows());
  const auto un = static_cast<std::size_t>(n);
  WardSlots slots{WardDistances(points, stop), std::vector<int>(un, 1), std::vector<char>(un, 1), n};
  return scipy_dendrogram(chain_merges(slots, stop), n);
}

void WardSettings::validate() const {
  if (max_clusters < 1) throw ParameterError("ward: max_clusters: " + std::to_string(max_clusters) + " < 1");
}

WardClustering::WardClustering(WardSettings settings) : settings_(settings) { settings_.validate(); }

Clustering WardClustering::cluster(const Eigen::MatrixXd& points, core::Rng& /*rng*/,
                                   const core::StopCondition* stop) const {
  const WardDendrogram tree = ward_linkage(points, stop);
  const int n = tree.n;
  const int max_c = std::min(settings_.max_clusters, n);
  // Merge i raises W by height^2 / 2, so W(c) = the sum of the first n - c raises.
  double total = 0.0;
  for (const WardMerge& m : tree.merges) total += 0.5 * m.height * m.height;
  Clustering out;
  out.curve.resize(static_cast<std::size_t>(max_c));
  double w = 0.0;
  for (int i = 0; i < n - 1; ++i) {
    w += 0.5 * tree.merges[static_cast<std::size_t>(i)].height * tree.merges[static_cast<std::size_t>(i)].height;
    const int c = n - 1 - i;  // clusters left after merge i
    if (c <= max_c) out.curve[static_cast<std::size_t>(c - 1)] = total > 0.0 ? w / total : 0.0;
  }
  if (max_c == n) out.curve[static_cast<std::size_t>(n - 1)] = 0.0;  // n singletons: W = 0
  out.curve[0] = total > 0.0 ? 1.0 : 0.0;
  const int c = elbow_choice(out.curve);
  out.labels = tree.cut(c);
  out.centres = cluster_means(points, out.labels, c);
  out.c = canonicalise(out.labels, out.centres);
  return out;
}

}  // namespace amp::learn
