#include "amp/nav/pgcs/trace_graph.hpp"

#include <algorithm>

#include "amp/nav/free_mask.hpp"
#include "amp/nav/pgcs/pgcs_explorer.hpp"
#include "amp/nav/pgcs/trace_corridor.hpp"

namespace amp::nav {

TraceGraph::TraceGraph(const PgcsExplorer& explorer, const TraceCorridor& corridor, const EdgeMemory& memory,
                       const EdgeMemory* blocked_now)
    : RouteGraph(explorer.clusters(), memory, blocked_now), explorer_(explorer), corridor_(corridor) {}

int TraceGraph::cell_label(int cell) {
  if (cell < 0) return -1;
  const learn::Pgcs& pgcs = explorer_.clusters();
  if (label_step_ != pgcs.steps()) {
    label_.assign(corridor_.geometry().cell_count(), -2);
    label_step_ = pgcs.steps();
  }
  int& l = label_[static_cast<std::size_t>(cell)];
  if (l == -2) l = pgcs.triangulation().nearest(corridor_.geometry().cell_center(cell));
  return l;
}

void TraceGraph::link() {
  const learn::Pgcs& pgcs = explorer_.clusters();
  if (links_step_ == pgcs.steps() && links_version_ == corridor_.version()) return;
  std::size_t ids = 0;
  for (int k : pgcs.ids()) ids = std::max(ids, static_cast<std::size_t>(k) + 1);
  for (auto& l : links_) l.clear();
  links_.resize(ids);
  const FreeMask& g = corridor_.geometry();
  const auto join = [&](int a, int b) {
    if (a < 0 || b < 0 || a == b) return;
    links_[static_cast<std::size_t>(a)].push_back(b);
    links_[static_cast<std::size_t>(b)].push_back(a);
  };
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      const int c = g.index(x, y);
      if (!corridor_.visited(c)) continue;
      if (x + 1 < g.width() && corridor_.visited(c + 1)) join(cell_label(c), cell_label(c + 1));
      if (y + 1 < g.height() && corridor_.visited(c + g.width())) join(cell_label(c), cell_label(c + g.width()));
    }
  }
  for (auto& l : links_) {
    std::sort(l.begin(), l.end());
    l.erase(std::unique(l.begin(), l.end()), l.end());
  }
  links_step_ = pgcs.steps();
  links_version_ = corridor_.version();
  ++links_made_;
}

bool TraceGraph::linked(int a, int b) const {
  if (a < 0 || static_cast<std::size_t>(a) >= links_.size()) return false;
  const std::vector<int>& l = links_[static_cast<std::size_t>(a)];
  return std::binary_search(l.begin(), l.end(), b);
}

void TraceGraph::append_links(int k, std::vector<int>& out) const {
  if (k >= 0 && static_cast<std::size_t>(k) < links_.size()) {
    out.insert(out.end(), links_[static_cast<std::size_t>(k)].begin(), links_[static_cast<std::size_t>(k)].end());
  }
}

int TraceGraph::home(const Eigen::Vector2d& p) {
  const int k = cell_label(corridor_.geometry().cell_of(p));
  return k >= 0 && explorer_.node_point(k).allFinite() ? k : -1;  // a cluster with no point is not in the graph
}

Eigen::Vector2d TraceGraph::point(int k) const { return explorer_.node_point(k); }

// Both counters only grow, so their sum changes whenever either does.
std::uint64_t TraceGraph::revision() const { return links_made_ + explorer_.revision(); }

}  // namespace amp::nav
