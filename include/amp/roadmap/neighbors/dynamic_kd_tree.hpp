#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <new>
#include <numeric>
#include <utility>
#include <vector>

#include "amp/core/state.hpp"

namespace amp::roadmap {

// Allocates on cache-line boundaries, so that a node's box does not straddle two lines.
template <class T>
struct AlignedAllocator {
  using value_type = T;
  static constexpr std::align_val_t kAlign{64};
  AlignedAllocator() = default;
  template <class U>
  AlignedAllocator(const AlignedAllocator<U>& /*other*/) {}
  T* allocate(std::size_t n) { return static_cast<T*>(::operator new(n * sizeof(T), kAlign)); }
  void deallocate(T* p, std::size_t /*n*/) { ::operator delete(p, kAlign); }
  template <class U>
  bool operator==(const AlignedAllocator<U>& /*other*/) const {
    return true;
  }
};

// One KD-tree that grows point by point, searched by branch and bound with a pluggable lower bound
// (kd_bounds.hpp) of the true metric over each node's bounding box.
//
// Insertion descends to a leaf and appends to its bucket (a full bucket is rebuilt into a small
// subtree). Balance is kept as in a scapegoat tree (Galperin & Rivest, SODA 1993): when a leaf lies
// deeper than log_{1/alpha}(n), the highest ancestor with a child holding more than alpha of its
// points is rebuilt at the median; and the whole tree is rebuilt each time n doubles, which
// restores median splits and a compact layout. On random insertion orders this costs amortised
// O(log n) per point (the doubling rebuilds: n log n work per n/2 insertions); an adversarial
// order adds the scapegoat rebuilds. Unlike a logarithmic forest of static trees, a query searches
// one tree.
//
// Bounding boxes are those of the points actually stored, so a search is exact whatever the
// split values and routing: a point is pruned only when the bound of its box exceeds the radius.
template <class Bound>
class DynamicKdTree {
 public:
  explicit DynamicKdTree(Bound bound) : bound_(std::move(bound)), dim_(bound_.dimension()) { rebuild_all(); }

  Bound& bound() { return bound_; }
  const Bound& bound() const { return bound_; }
  std::size_t size() const { return size_; }

  void reserve(std::size_t n) {
    coords_.reserve(n * static_cast<std::size_t>(dim_));
    ids_.reserve(n);
  }

  // Stores s as point id size().
  void insert(const State& s) {
    const auto id = static_cast<std::uint32_t>(size_++);
    coords_.resize(size_ * static_cast<std::size_t>(dim_));
    bound_.store(s, point(id));
    if (size_ >= kMinFullRebuild && size_ > 2 * built_size_) {
      rebuild_all();
      return;
    }
    const double* x = point(id);
    path_.clear();
    std::uint32_t node = root_;
    for (;;) {
      path_.push_back(node);
      grow_box(node, x);
      Node& n = nodes_[node];
      ++n.count;
      if (n.is_leaf()) break;
      node = x[n.split_dim] < n.split ? n.left : n.right;
    }
    Node& leaf = nodes_[node];
    if (leaf.count <= kBucket) {
      store_slot(static_cast<std::size_t>(leaf.bucket) * kBucket + leaf.count - 1, id);
      sync_hot(node);
    } else {
      rebuild_subtree(node, id);  // the bucket overflowed: split it
    }
    if (static_cast<double>(path_.size()) > depth_limit()) rebalance();
  }

  // Branch and bound over the tree, after bound().prepare(query). The visitor provides
  // `double radius() const` (prune beyond it) and `void visit(std::uint32_t id)`.
  template <class Visitor>
  void search(Visitor& v) const {
    if (box_bound(root_, v.radius()) <= v.radius()) search_node(root_, v);
  }

  // Longest root-to-leaf path, in nodes (tests check balance with it).
  std::size_t depth() const { return depth_below(root_); }
  // The bound's stored coordinates of point id.
  const double* point(std::uint32_t id) const { return coords_.data() + static_cast<std::size_t>(id) * dim_; }

 private:
  static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  // A leaf built from scratch holds at most kLeafSize points and fills up to kBucket before it
  // splits. Measured on 10-NN among 100k SE3 states: leaves of 16 beat 4-8 (fewer boxes, each a
  // cache miss); 24-32 were no faster.
  static constexpr std::uint32_t kLeafSize = 16;
  static constexpr std::uint32_t kBucket = 32;
  static constexpr double kAlpha = 0.75;  // scapegoat balance: no child above 3/4 of its parent
  static constexpr std::size_t kMinFullRebuild = 64;
  static constexpr std::uint32_t kLeafFlag = 0x80000000u;

  struct Node {
    std::uint32_t left = kNone, right = kNone;
    std::uint32_t bucket = kNone;  // leaf: its slots are bucket * kBucket + [0, count)
    std::uint32_t count = 0;       // points in the subtree
    int split_dim = 0;
    double split = 0.0;  // routing of insertions: x[split_dim] < split goes left
    bool is_leaf() const { return left == kNone; }
  };

  double* point(std::uint32_t id) { return coords_.data() + static_cast<std::size_t>(id) * dim_; }
  float* box(std::uint32_t node) { return boxes_.data() + static_cast<std::size_t>(node) * box_stride_; }
  const float* box(std::uint32_t node) const { return boxes_.data() + static_cast<std::size_t>(node) * box_stride_; }
  double box_bound(std::uint32_t node, double r) const {
    const float* b = box(node);
    return bound_.box(b, b + dim_, r);
  }
  // Boxes are stored in float, rounded outwards so that they still contain their points: half the
  // memory, and one cache line per node up to 7 coordinates (the search is bound by memory).
  // One float ulp is at most 2^-23 |f|; the denormal covers f == 0.
  static float round_down(double x) {
    const auto f = static_cast<float>(x);
    return static_cast<double>(f) > x ? f - std::abs(f) * 0x1.0p-23f - 0x1.0p-149f : f;
  }
  static float round_up(double x) {
    const auto f = static_cast<float>(x);
    return static_cast<double>(f) < x ? f + std::abs(f) * 0x1.0p-23f + 0x1.0p-149f : f;
  }
  void grow_box(std::uint32_t node, const double* x) {
    float* b = box(node);
    for (int d = 0; d < dim_; ++d) {
      b[d] = std::min(b[d], round_down(x[d]));
      b[dim_ + d] = std::max(b[dim_ + d], round_up(x[d]));
    }
  }
  double depth_limit() const {
    return std::log(static_cast<double>(size_)) / std::log(1.0 / kAlpha) + 2.0;
  }

  template <class Visitor>
  void search_node(std::uint32_t node, Visitor& v) const {
    const std::uint32_t child = hot(node, 0), info = hot(node, 1);
    if ((info & kLeafFlag) != 0) {
      const std::size_t first = static_cast<std::size_t>(child) * kBucket;
      for (std::size_t s = first; s < first + (info & ~kLeafFlag); ++s) {
        const double r = v.radius() + point_slack_;
        if (bound_.point(slot_coords_.data() + s * point_stride_, r) <= r) v.visit(slot_ids_[s]);
      }
      return;
    }
    const double r = v.radius();
    double near_bound = box_bound(child, r), far_bound = box_bound(child + 1, r);
    std::uint32_t near = child, far = child + 1;
    if (far_bound < near_bound) {
      std::swap(near, far);
      std::swap(near_bound, far_bound);
    }
    if (near_bound <= v.radius()) search_node(near, v);
    if (far_bound <= v.radius()) search_node(far, v);
  }

  // A node's box line also holds what the search needs to go on, so that a level of the search
  // costs one cache miss (the two children's lines are adjacent): its first child (an internal
  // node; the second is next to it) or its bucket (a leaf), and its point count | kLeafFlag (a
  // leaf) or 0.
  std::uint32_t hot(std::uint32_t node, int field) const {
    std::uint32_t value;
    std::memcpy(&value, box(node) + 2 * dim_ + field, sizeof value);
    return value;
  }
  void sync_hot(std::uint32_t node) {
    const Node& n = nodes_[node];
    const std::uint32_t fields[2] = {n.is_leaf() ? n.bucket : n.left, n.is_leaf() ? (n.count | kLeafFlag) : 0u};
    std::memcpy(box(node) + 2 * dim_, fields, sizeof fields);
  }

  std::size_t depth_below(std::uint32_t node) const {
    const Node& n = nodes_[node];
    return n.is_leaf() ? 1 : 1 + std::max(depth_below(n.left), depth_below(n.right));
  }

  // Siblings are allocated as a pair (first index even), so their box lines are adjacent.
  std::uint32_t allocate_pair() {
    if (!free_pairs_.empty()) {
      const std::uint32_t n = free_pairs_.back();
      free_pairs_.pop_back();
      nodes_[n] = nodes_[n + 1] = Node{};
      return n;
    }
    nodes_.resize(nodes_.size() + 2);
    boxes_.resize(nodes_.size() * box_stride_);
    return static_cast<std::uint32_t>(nodes_.size() - 2);
  }
  std::uint32_t allocate_bucket() {
    if (!free_buckets_.empty()) {
      const std::uint32_t b = free_buckets_.back();
      free_buckets_.pop_back();
      return b;
    }
    const auto b = static_cast<std::uint32_t>(slot_ids_.size() / kBucket);
    slot_ids_.resize(slot_ids_.size() + kBucket);
    slot_coords_.resize(slot_ids_.size() * point_stride_);
    return b;
  }

  // Leaf copies of the points are floats too (the bound is then only a filter before the true
  // distance): point_slack_ covers their rounding, up to the largest coordinate stored.
  void store_slot(std::size_t slot, std::uint32_t id) {
    slot_ids_[slot] = id;
    const double* x = point(id);
    float* out = slot_coords_.data() + slot * point_stride_;
    for (int d = 0; d < dim_; ++d) {
      out[d] = static_cast<float>(x[d]);
      max_abs_ = std::max(max_abs_, std::abs(x[d]));
    }
    point_slack_ = bound_.float_slack(max_abs_);
  }

  void rebuild_all() {
    nodes_.clear();
    boxes_.clear();
    slot_ids_.clear();
    slot_coords_.clear();
    free_pairs_.clear();
    free_buckets_.clear();
    ids_.resize(size_);
    std::iota(ids_.begin(), ids_.end(), 0u);
    root_ = allocate_pair();  // its sibling stays unused
    build(root_, 0, size_);
    built_size_ = size_;
  }

  // Rebuilds the subtree at `node` in place (its index is kept, so its parent is unchanged), with
  // `extra` (a point routed there but not yet stored) when it is not kNone.
  void rebuild_subtree(std::uint32_t node, std::uint32_t extra) {
    ids_.clear();
    collect(node);
    if (extra != kNone) ids_.push_back(extra);
    build(node, 0, ids_.size());
  }
  void collect(std::uint32_t node) {
    const Node n = nodes_[node];
    if (n.is_leaf()) {
      const std::size_t first = static_cast<std::size_t>(n.bucket) * kBucket;
      const std::size_t stored = std::min<std::size_t>(n.count, kBucket);
      ids_.insert(ids_.end(), slot_ids_.begin() + static_cast<std::ptrdiff_t>(first),
                  slot_ids_.begin() + static_cast<std::ptrdiff_t>(first + stored));
      free_buckets_.push_back(n.bucket);
    } else {
      collect(n.left);
      collect(n.right);
      free_pairs_.push_back(n.left);
    }
  }

  // The highest node on the last insertion path that is out of alpha-balance, rebuilt.
  void rebalance() {
    for (std::uint32_t node : path_) {
      const Node& n = nodes_[node];
      if (n.is_leaf()) return;
      const std::uint32_t big = std::max(nodes_[n.left].count, nodes_[n.right].count);
      if (static_cast<double>(big) > kAlpha * static_cast<double>(n.count)) {
        rebuild_subtree(node, kNone);
        return;
      }
    }
  }

  // Builds ids_[first, last) under `node` (already allocated): median split on the widest
  // coordinate, widths weighted by the bound's distance per unit.
  void build(std::uint32_t node, std::size_t first, std::size_t last) {
    float* b = box(node);
    std::fill(b, b + dim_, std::numeric_limits<float>::infinity());
    std::fill(b + dim_, b + 2 * dim_, -std::numeric_limits<float>::infinity());
    for (std::size_t i = first; i < last; ++i) grow_box(node, point(ids_[i]));
    const auto count = static_cast<std::uint32_t>(last - first);
    int split_dim = 0;
    double widest = -1.0;
    for (int d = 0; d < dim_; ++d) {
      const double w = (static_cast<double>(b[dim_ + d]) - b[d]) * bound_.split_scale(d);
      if (w > widest) {
        widest = w;
        split_dim = d;
      }
    }
    // Identical points cannot be separated by coordinates: keep them in one leaf while they fit.
    if (count <= kLeafSize || (widest <= 0.0 && count <= kBucket)) {
      const std::uint32_t bucket = allocate_bucket();
      Node& n = nodes_[node];
      n = Node{};
      n.bucket = bucket;
      n.count = count;
      const std::size_t slot = static_cast<std::size_t>(bucket) * kBucket;
      for (std::uint32_t i = 0; i < count; ++i) store_slot(slot + i, ids_[first + i]);
      sync_hot(node);
      return;
    }
    const std::size_t mid = first + count / 2;
    const auto begin = ids_.begin();
    std::nth_element(begin + static_cast<std::ptrdiff_t>(first), begin + static_cast<std::ptrdiff_t>(mid),
                     begin + static_cast<std::ptrdiff_t>(last), [&](std::uint32_t a, std::uint32_t c) {
                       return point(a)[split_dim] < point(c)[split_dim];
                     });
    const double split = point(ids_[mid])[split_dim];
    const std::uint32_t left = allocate_pair();
    const std::uint32_t right = left + 1;
    nodes_[node] = Node{left, right, kNone, count, split_dim, split};
    sync_hot(node);
    build(left, first, mid);
    build(right, mid, last);
  }

  Bound bound_;
  int dim_;
  std::size_t size_ = 0;
  std::size_t built_size_ = 0;
  std::uint32_t root_ = 0;
  std::vector<double> coords_;  // by point id: the bound's coordinates (what rebuilds read)
  std::vector<Node> nodes_;
  std::size_t box_stride_ = (2 * static_cast<std::size_t>(dim_) + 2 + 15) / 16 * 16;  // floats, whole lines
  std::vector<float, AlignedAllocator<float>> boxes_;  // by node: lo[dim], hi[dim] of the points below
  std::vector<std::uint32_t> slot_ids_;  // by bucket slot: point id
  std::size_t point_stride_ = dim_ <= 8 ? 8 : static_cast<std::size_t>(dim_);
  std::vector<float, AlignedAllocator<float>> slot_coords_;  // by slot: the point in float, for locality
  double max_abs_ = 0.0;      // largest |coordinate| stored
  double point_slack_ = 0.0;  // what rounding to float can take off a point's bound
  std::vector<std::uint32_t> free_pairs_, free_buckets_;  // first of a free sibling pair; free buckets
  std::vector<std::uint32_t> ids_;   // rebuild scratch
  std::vector<std::uint32_t> path_;  // insertion scratch: root to leaf
};

}  // namespace amp::roadmap
