#include "amp/roadmap/roadmap.hpp"

#include <algorithm>
#include <cassert>

namespace amp::roadmap {

void Roadmap::reserve(std::size_t nodes, std::size_t degree) {
  states_.reserve(nodes);
  adjacency_.reserve(nodes);
  components_.reserve(nodes);
  degree_hint_ = degree;
}

VertexId Roadmap::add_vertex(const State& s) {
  states_.push_back(s);
  adjacency_.emplace_back();
  adjacency_.back().reserve(degree_hint_);
  components_.add();
  return states_.size() - 1;
}

void Roadmap::add_edge(VertexId a, VertexId b, double cost, EdgeCheck check) {
  assert(a != b && a < states_.size() && b < states_.size());
  adjacency_[a].push_back({b, cost, check});
  adjacency_[b].push_back({a, cost, check});
  ++edge_count_;
  if (!components_stale_) components_.unite(a, b);
}

bool Roadmap::remove_edge(VertexId a, VertexId b) {
  auto erase_from = [](std::vector<Edge>& list, VertexId to) {
    const auto it = std::find_if(list.begin(), list.end(), [to](const Edge& e) { return e.to == to; });
    if (it == list.end()) return false;
    list.erase(it);  // keeps the order of the other edges, so searches stay deterministic
    return true;
  };
  if (!erase_from(adjacency_[a], b)) return false;
  erase_from(adjacency_[b], a);
  --edge_count_;
  components_stale_ = true;
  return true;
}

bool Roadmap::has_edge(VertexId a, VertexId b) const {
  const auto& list = adjacency_[a];
  return std::any_of(list.begin(), list.end(), [b](const Edge& e) { return e.to == b; });
}

void Roadmap::mark(VertexId a, VertexId b, EdgeCheck check) {
  for (Edge& e : adjacency_[a]) {
    if (e.to == b) e.check = check;
  }
  for (Edge& e : adjacency_[b]) {
    if (e.to == a) e.check = check;
  }
}

EdgeCheck Roadmap::edge_check(VertexId a, VertexId b) const {
  for (const Edge& e : adjacency_[a]) {
    if (e.to == b) return e.check;
  }
  return EdgeCheck::kUnchecked;
}

void Roadmap::refresh_components() const {
  if (!components_stale_) return;
  components_.reset();
  for (VertexId v = 0; v < adjacency_.size(); ++v) {
    for (const Edge& e : adjacency_[v]) {
      if (e.to > v) components_.unite(v, e.to);
    }
  }
  components_stale_ = false;
}

VertexId Roadmap::component(VertexId v) const {
  refresh_components();
  return components_.find(v);
}

std::size_t Roadmap::component_count() const {
  refresh_components();
  return components_.set_count();
}

}  // namespace amp::roadmap
