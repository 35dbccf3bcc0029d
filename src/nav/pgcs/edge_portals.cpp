#include "amp/nav/pgcs/edge_portals.hpp"

#include <algorithm>

namespace amp::nav {

void EdgePortals::observe(int a, long born_a, int b, long born_b, const Eigen::Vector2d& crossing) {
  if (a > b) std::swap(a, b), std::swap(born_a, born_b);
  Portal& p = portals_[{a, b}];
  if (p.crossings == 0 || p.born_a != born_a || p.born_b != born_b) p = Portal{born_a, born_b, 0, crossing};
  p.crossings = std::min(p.crossings + 1, memory_);
  p.mean += (crossing - p.mean) / static_cast<double>(p.crossings);
}

const Eigen::Vector2d* EdgePortals::find(int a, long born_a, int b, long born_b) const {
  if (a > b) std::swap(a, b), std::swap(born_a, born_b);
  const auto it = portals_.find({a, b});
  if (it == portals_.end() || it->second.born_a != born_a || it->second.born_b != born_b) return nullptr;
  return &it->second.mean;
}

}  // namespace amp::nav
