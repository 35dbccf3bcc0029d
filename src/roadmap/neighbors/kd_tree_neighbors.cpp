#include "amp/roadmap/neighbors/kd_tree_neighbors.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>

#include "amp/roadmap/neighbors/dynamic_kd_tree.hpp"
#include "amp/roadmap/neighbors/kd_bounds.hpp"

namespace amp::roadmap {

namespace {

// The prune radius is the current k-th true distance, inflated so that neither the rounding of the
// bounds (computed differently from space.distance) nor exact ties can exclude a point that belongs
// in the answer: a point with true distance equal to the k-th must still reach the index tie-break.
constexpr double kRelativeSlack = 1e-9;
constexpr double kAbsoluteSlackPerExtent = 1e-12;

}  // namespace

// The tree behind the interface, one per bound policy.
struct KdTreeNeighbors::Impl {
  virtual ~Impl() = default;
  virtual void add(std::size_t index, const State& s) = 0;
  virtual void k_nearest(const State& q, std::size_t k, std::vector<Neighbor>& out) = 0;
  virtual std::size_t size() const = 0;
  virtual void reserve(std::size_t n) = 0;
  std::size_t evaluations = 0;
};

namespace {

template <class Bound>
class TreeImpl final : public KdTreeNeighbors::Impl {
 public:
  TreeImpl(const core::Space& space, Bound bound)
      : space_(&space), absolute_slack_(kAbsoluteSlackPerExtent * space.maximum_extent()), tree_(std::move(bound)) {}

  void add(std::size_t index, const State& s) override {
    tree_.insert(s);
    states_.push_back(s);
    indices_.push_back(index);
  }
  std::size_t size() const override { return states_.size(); }
  void reserve(std::size_t n) override {
    tree_.reserve(n);
    states_.reserve(n);
    indices_.reserve(n);
  }

  void k_nearest(const State& q, std::size_t k, std::vector<Neighbor>& out) override {
    evaluations = 0;
    k = std::min(k, states_.size());
    if (k == 0) return;
    tree_.bound().prepare(q);
    Result result(*this, q, k, out, absolute_slack_ + tree_.bound().slack());
    tree_.search(result);
  }

 private:
  // Keeps the k best states by TRUE distance (ties by index) and prunes beyond the k-th, inflated.
  class Result {
   public:
    Result(TreeImpl& m, const State& q, std::size_t k, std::vector<Neighbor>& best, double slack)
        : m_(m), q_(q), k_(k), best_(best), slack_(slack) {}

    double radius() const { return radius_; }
    void visit(std::uint32_t id) {
      ++m_.evaluations;
      const Neighbor n{m_.indices_[id], m_.space_->distance(q_, m_.states_[id])};
      if (best_.size() == k_) {
        if (!(n < best_.back())) return;
        best_.pop_back();
      }
      best_.insert(std::upper_bound(best_.begin(), best_.end(), n), n);
      if (best_.size() == k_) radius_ = best_.back().distance * (1.0 + kRelativeSlack) + slack_;
    }

   private:
    TreeImpl& m_;
    const State& q_;
    std::size_t k_;
    std::vector<Neighbor>& best_;
    double slack_;
    double radius_ = std::numeric_limits<double>::infinity();
  };

  const core::Space* space_;
  double absolute_slack_;
  DynamicKdTree<Bound> tree_;
  std::vector<State> states_;         // by point id, for the true distance
  std::vector<std::size_t> indices_;  // by point id: the caller's index
};

std::unique_ptr<KdTreeNeighbors::Impl> make_impl(const core::Space& space) {
  const std::optional<core::CoordinateLayout> layout = space.coordinate_layout();
  if (layout && layout->rigid_body_3d()) {
    return std::make_unique<TreeImpl<Se3Bound>>(space, Se3Bound(*layout));
  }
  return std::make_unique<TreeImpl<EmbeddingBound>>(space, EmbeddingBound(space));
}

}  // namespace

KdTreeNeighbors::KdTreeNeighbors(const core::Space& space, core::Counters* counters)
    : counters_(counters), impl_(make_impl(space)) {}

KdTreeNeighbors::~KdTreeNeighbors() = default;

std::size_t KdTreeNeighbors::size() const { return impl_->size(); }

std::size_t KdTreeNeighbors::last_distance_evaluations() const { return impl_->evaluations; }

void KdTreeNeighbors::reserve(std::size_t n) { impl_->reserve(n); }

void KdTreeNeighbors::add(std::size_t index, const State& s) { impl_->add(index, s); }

void KdTreeNeighbors::k_nearest(const State& q, std::size_t k, std::vector<Neighbor>& out) const {
  if (counters_ != nullptr) counters_->add_nn_query();
  out.clear();
  impl_->k_nearest(q, k, out);
}

}  // namespace amp::roadmap
