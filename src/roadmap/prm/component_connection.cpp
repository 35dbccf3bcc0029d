#include "amp/roadmap/prm/component_connection.hpp"

#include <algorithm>
#include <tuple>

#include "amp/roadmap/roadmap.hpp"

namespace amp::roadmap {

ComponentNearestConnection::ComponentNearestConnection(const core::Space& space, std::size_t k)
    : space_(&space), k_(k) {}

void ComponentNearestConnection::add(VertexId v, const State&) { added_.push_back(v); }

void ComponentNearestConnection::candidates(const Roadmap& roadmap, VertexId v, std::vector<Neighbor>& out) {
  out.clear();
  scratch_.clear();
  const State& q = roadmap.state(v);
  for (const VertexId u : added_) {
    if (u == v) continue;
    scratch_.push_back(Entry{space_->distance(q, roadmap.state(u)), roadmap.component(u), u});
  }
  // Per component nearest first, then keep the first k of each.
  std::sort(scratch_.begin(), scratch_.end(), [](const Entry& a, const Entry& b) {
    return std::tie(a.component, a.distance, a.id) < std::tie(b.component, b.distance, b.id);
  });
  std::size_t taken = 0;
  for (std::size_t i = 0; i < scratch_.size(); ++i) {
    taken = (i > 0 && scratch_[i].component == scratch_[i - 1].component) ? taken + 1 : 0;
    if (taken < k_) out.push_back(Neighbor{scratch_[i].id, scratch_[i].distance});
  }
  std::sort(out.begin(), out.end());
}

}  // namespace amp::roadmap
