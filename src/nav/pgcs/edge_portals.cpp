#include "amp/nav/pgcs/edge_portals.hpp"

#include <algorithm>

namespace amp::nav {

void EdgePortals::observe(int a, long born_a, int b, long born_b, const Eigen::Vector2d& crossing) {
  if (a > b) std::swap(a, b), std::swap(born_a, born_b);
  const auto [it, fresh] = portals_.try_emplace(key(a, b));
  Portal& p = it->second;
  if (fresh) {
    if (static_cast<std::size_t>(b) >= crossed_.size()) crossed_.resize(static_cast<std::size_t>(b) + 1);
    for (auto [x, y] : {std::pair{a, b}, std::pair{b, a}}) {
      std::vector<int>& c = crossed_[static_cast<std::size_t>(x)];
      c.insert(std::lower_bound(c.begin(), c.end(), y), y);
    }
  }
  if (p.crossings == 0 || p.born_a != born_a || p.born_b != born_b) p = Portal{born_a, born_b, 0, crossing};
  p.crossings = std::min(p.crossings + 1, memory_);
  p.mean += (crossing - p.mean) / static_cast<double>(p.crossings);
}

const std::vector<int>& EdgePortals::crossed(int a) const {
  static const std::vector<int> kNone;
  return static_cast<std::size_t>(a) < crossed_.size() ? crossed_[static_cast<std::size_t>(a)] : kNone;
}

const Eigen::Vector2d* EdgePortals::find(int a, long born_a, int b, long born_b) const {
  if (a > b) std::swap(a, b), std::swap(born_a, born_b);
  const auto it = portals_.find(key(a, b));
  if (it == portals_.end() || it->second.born_a != born_a || it->second.born_b != born_b) return nullptr;
  return &it->second.mean;
}

void EdgePortals::forget(int a) {
  if (static_cast<std::size_t>(a) >= crossed_.size()) return;
  for (int b : crossed_[static_cast<std::size_t>(a)]) {
    portals_.erase(a < b ? key(a, b) : key(b, a));
    std::vector<int>& c = crossed_[static_cast<std::size_t>(b)];
    c.erase(std::lower_bound(c.begin(), c.end(), a));
  }
  crossed_[static_cast<std::size_t>(a)].clear();
}

void EdgePortals::drop(int a, int b) {
  if (a > b) std::swap(a, b);
  if (portals_.erase(key(a, b)) == 0) return;
  for (auto [x, y] : {std::pair{a, b}, std::pair{b, a}}) {
    std::vector<int>& c = crossed_[static_cast<std::size_t>(x)];
    c.erase(std::lower_bound(c.begin(), c.end(), y));
  }
}

}  // namespace amp::nav
