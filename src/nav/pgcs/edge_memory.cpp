#include "amp/nav/pgcs/edge_memory.hpp"

namespace amp::nav {

void EdgeMemory::mark(int a, int b, const Eigen::Vector2d& pa, const Eigen::Vector2d& pb) {
  if (a > b) return mark(b, a, pb, pa);
  edges_[{a, b}] = {pa, pb};
}

bool EdgeMemory::illegal(int a, int b, const Eigen::Vector2d& pa, const Eigen::Vector2d& pb) const {
  if (a > b) return illegal(b, a, pb, pa);
  const auto it = edges_.find({a, b});
  if (it == edges_.end()) return false;
  return (it->second.first - pa).squaredNorm() <= tolerance2_ && (it->second.second - pb).squaredNorm() <= tolerance2_;
}

std::vector<EdgeMemory::Entry> EdgeMemory::entries() const {
  std::vector<Entry> out;
  out.reserve(edges_.size());
  for (const auto& [k, v] : edges_) out.push_back({k.first, k.second, v.first, v.second});
  return out;
}

}  // namespace amp::nav
