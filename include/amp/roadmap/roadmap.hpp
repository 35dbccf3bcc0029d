#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "amp/core/state.hpp"
#include "amp/roadmap/disjoint_sets.hpp"

namespace amp::roadmap {

using VertexId = std::size_t;

// Whether the local planner has confirmed an edge. Lazy planners add edges unchecked and validate
// only those on a candidate path.
// kValid: checked at the space's resolution; kCertified: proven free along its whole length
// (EdgeCertifier).
enum class EdgeCheck : std::uint8_t { kUnchecked = 0, kValid = 1, kCertified = 2 };

// One direction of an undirected edge, stored in the adjacency list of its source.
struct Edge {
  VertexId to = 0;
  double cost = 0.0;
  EdgeCheck check = EdgeCheck::kValid;
};

// An undirected graph of configurations. States are stored contiguously (one array: cache-friendly);
// connected components are kept by union-find as edges are added. Removing an edge cannot be undone
// in a union-find, so remove_edge() marks components stale and the next component query rebuilds
// them from the remaining edges (O(V + E), paid only by lazy planners after a failed edge).
class Roadmap {
 public:
  // Reserves room for `nodes` vertices with about `degree` edges each (the planner's budget).
  void reserve(std::size_t nodes, std::size_t degree);

  VertexId add_vertex(const State& s);
  // Adds the undirected edge a-b (a != b) and joins the endpoints' components. Does not check for
  // duplicates: use has_edge() first where that matters.
  void add_edge(VertexId a, VertexId b, double cost, EdgeCheck check = EdgeCheck::kValid);
  // Removes a-b if present; returns whether it was.
  bool remove_edge(VertexId a, VertexId b);
  bool has_edge(VertexId a, VertexId b) const;
  // Marks both directions of a-b (which must exist) as checked.
  void mark_valid(VertexId a, VertexId b) { mark(a, b, EdgeCheck::kValid); }
  void mark(VertexId a, VertexId b, EdgeCheck check);
  // How a-b was checked (kUnchecked when there is no such edge).
  EdgeCheck edge_check(VertexId a, VertexId b) const;

  const State& state(VertexId v) const { return states_[v]; }
  const std::vector<State>& states() const { return states_; }
  const std::vector<Edge>& edges(VertexId v) const { return adjacency_[v]; }
  std::size_t vertex_count() const { return states_.size(); }
  std::size_t edge_count() const { return edge_count_; }

  // Representative vertex of v's connected component.
  VertexId component(VertexId v) const;
  bool same_component(VertexId a, VertexId b) const { return component(a) == component(b); }
  std::size_t component_count() const;
  // Whether an edge was removed since the components were last built: the next component query
  // rebuilds them, O(V + E). A planner that can answer its question otherwise (a repaired search)
  // asks this first.
  bool components_stale() const { return components_stale_; }

 private:
  void refresh_components() const;

  std::vector<State> states_;
  std::vector<std::vector<Edge>> adjacency_;
  std::size_t edge_count_ = 0;
  std::size_t degree_hint_ = 0;
  mutable DisjointSets components_;
  mutable bool components_stale_ = false;
};

}  // namespace amp::roadmap
