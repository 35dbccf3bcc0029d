#include "amp/roadmap/kd_tree_neighbors.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include <nanoflann.hpp>

namespace amp::roadmap {

namespace {

// The prune radius is the current k-th true distance, inflated so that neither the rounding of the
// embedding (a different sum from space.distance) nor exact ties can exclude a point that belongs
// in the answer: a point with true distance equal to the k-th must still reach the index tie-break.
constexpr double kRelativeSlack = 1e-9;
constexpr double kAbsoluteSlackPerExtent = 1e-12;
// nanoflann leaf size: small leaves suit the small k of roadmap planners.
constexpr std::size_t kLeafSize = 8;

// Embedded coordinates of every stored state, row after row: what nanoflann reads.
struct EmbeddedPoints {
  std::vector<double> coords;
  std::size_t dim = 0;

  std::size_t kdtree_get_point_count() const { return dim == 0 ? 0 : coords.size() / dim; }
  double kdtree_get_pt(std::size_t idx, std::size_t d) const { return coords[idx * dim + d]; }
  template <class Bbox>
  bool kdtree_get_bbox(Bbox& /*bb*/) const {
    return false;
  }
};

using Metric = nanoflann::L2_Adaptor<double, EmbeddedPoints, double, std::uint32_t>;
using Tree = nanoflann::KDTreeSingleIndexDynamicAdaptor<Metric, EmbeddedPoints, -1, std::uint32_t>;

}  // namespace

struct KdTreeNeighbors::Impl {
  Impl(const core::Space& s, core::Counters* c)
      : space(&s),
        counters(c),
        variants(s.embedding_variants()),
        absolute_slack(kAbsoluteSlackPerExtent * s.maximum_extent()),
        tree(s.embedding_dimension(), points, nanoflann::KDTreeSingleIndexAdaptorParams(kLeafSize)) {
    points.dim = static_cast<std::size_t>(s.embedding_dimension());
    query.resize(points.dim);
    box_dists.resize(points.dim);
  }

  // A nanoflann result set that keeps the k best states by TRUE distance (ties by index) and tells
  // the tree to prune at the k-th true distance: sound because the embedded distance of every state
  // is at most its true distance. The answer is therefore exact in a single pass.
  class ExactResult {
   public:
    using DistanceType = double;
    using IndexType = std::uint32_t;

    ExactResult(const Impl& m, const State& q, std::size_t k, std::vector<Neighbor>& best)
        : m_(m), q_(q), k_(k), best_(best) {}

    double worstDist() const { return prune_sq_; }
    bool addPoint(double /*embedded_sq*/, std::uint32_t id) {
      ++m_.evaluations;
      const Neighbor n{m_.indices[id], m_.space->distance(q_, m_.states[id])};
      if (best_.size() == k_ && !(n < best_.back())) return true;
      const auto at = std::lower_bound(best_.begin(), best_.end(), n);
      if (at != best_.end() && *at == n) return true;  // found again under another embedding variant
      if (best_.size() == k_) best_.pop_back();
      best_.insert(std::lower_bound(best_.begin(), best_.end(), n), n);
      if (best_.size() == k_) {
        const double r = best_.back().distance * (1.0 + kRelativeSlack) + m_.absolute_slack;
        prune_sq_ = r * r;
      }
      return true;
    }

   private:
    const Impl& m_;
    const State& q_;
    std::size_t k_;
    std::vector<Neighbor>& best_;
    double prune_sq_ = std::numeric_limits<double>::infinity();
  };

  // Searches every non-empty sub-tree with our own distance buffer: nanoflann's findNeighbors
  // allocates one per sub-tree and query when the dimension is dynamic.
  // Largest sub-tree first: it sets a tight bound early, so the small ones are pruned at once.
  void search(const double* q, ExactResult& result) const {
    const auto& subs = tree.getAllIndices();
    for (auto it = subs.rbegin(); it != subs.rend(); ++it) {
      const auto& sub = *it;
      if (sub.root_node == nullptr || sub.vAcc.empty()) continue;
      std::fill(box_dists.begin(), box_dists.end(), 0.0);
      const double d0 = sub.computeInitialDistances(sub, q, box_dists);
      sub.searchLevel(result, q, sub.root_node, d0, box_dists, 1.0f);
    }
  }

  const core::Space* space;
  core::Counters* counters;
  int variants;
  double absolute_slack;
  EmbeddedPoints points;
  Tree tree;
  std::vector<State> states;         // by point id, for the true distance
  std::vector<std::size_t> indices;  // by point id: the caller's index
  // Query scratch, reused so that a query does not allocate once warmed up.
  mutable std::vector<double> query;
  mutable std::vector<double> box_dists;
  mutable std::size_t evaluations = 0;
};

KdTreeNeighbors::KdTreeNeighbors(const core::Space& space, core::Counters* counters)
    : impl_(std::make_unique<Impl>(space, counters)) {}

KdTreeNeighbors::~KdTreeNeighbors() = default;

std::size_t KdTreeNeighbors::size() const { return impl_->states.size(); }

std::size_t KdTreeNeighbors::last_distance_evaluations() const { return impl_->evaluations; }

void KdTreeNeighbors::reserve(std::size_t n) {
  impl_->points.coords.reserve(n * impl_->points.dim);
  impl_->states.reserve(n);
  impl_->indices.reserve(n);
}

void KdTreeNeighbors::add(std::size_t index, const State& s) {
  Impl& m = *impl_;
  const std::size_t id = m.states.size();
  m.points.coords.resize((id + 1) * m.points.dim);
  m.space->embed(s, m.points.coords.data() + id * m.points.dim);
  m.states.push_back(s);
  m.indices.push_back(index);
  m.tree.addPoints(static_cast<std::uint32_t>(id), static_cast<std::uint32_t>(id));
}

void KdTreeNeighbors::k_nearest(const State& q, std::size_t k, std::vector<Neighbor>& out) const {
  Impl& m = *impl_;
  if (m.counters != nullptr) m.counters->add_nn_query();
  out.clear();
  m.evaluations = 0;
  k = std::min(k, m.states.size());
  if (k == 0) return;
  // One result set across the variants: the second search starts with the first's bound.
  Impl::ExactResult result(m, q, k, out);
  for (int v = 0; v < m.variants; ++v) {
    m.space->embed_variant(q, v, m.query.data());
    m.search(m.query.data(), result);
  }
}

}  // namespace amp::roadmap
