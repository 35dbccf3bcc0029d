#include "amp/nav/pgcs/edge_memory.hpp"

#include <algorithm>

namespace amp::nav {

void EdgeMemory::mark(int a, int b, const Eigen::Vector2d& pa, const Eigen::Vector2d& pb) {
  if (a > b) return mark(b, a, pb, pa);
  const int before = blocks(a, b, pa, pb);
  edges_[{a, b}] = {pa, pb, before + 1};
  if (b >= 0 && static_cast<std::size_t>(b) >= touched_.size()) touched_.resize(static_cast<std::size_t>(b) + 1, 0);
  for (const int id : {a, b}) {
    if (id >= 0) touched_[static_cast<std::size_t>(id)] = 1;
  }
}

int EdgeMemory::recorded_blocks(int a, int b, const Eigen::Vector2d& pa, const Eigen::Vector2d& pb) const {
  if (a > b) return recorded_blocks(b, a, pb, pa);
  const auto it = edges_.find({a, b});
  if (it == edges_.end()) return 0;
  const bool same = (it->second.pa - pa).squaredNorm() <= tolerance2_ && (it->second.pb - pb).squaredNorm() <= tolerance2_;
  return same ? it->second.blocks : 0;
}

std::size_t EdgeMemory::size() const {
  return static_cast<std::size_t>(
      std::count_if(edges_.begin(), edges_.end(), [&](const auto& e) { return e.second.blocks >= strikes_; }));
}

std::size_t EdgeMemory::suspects() const { return edges_.size() - size(); }

std::vector<EdgeMemory::Entry> EdgeMemory::entries() const {
  std::vector<Entry> out;
  out.reserve(edges_.size());
  for (const auto& [k, v] : edges_) out.push_back({k.first, k.second, v.pa, v.pb, v.blocks});
  return out;
}

}  // namespace amp::nav
