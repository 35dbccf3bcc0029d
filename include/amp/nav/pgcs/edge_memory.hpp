#pragma once
#include <cstddef>
#include <map>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace amp::nav {

// The graph edges a robot found blocked (Vlassis et al.'s "legal-illegal" map connections), kept
// across queries. An edge is named by its clusters' ids and remembered with where its ends were:
// it stays illegal while both ends are within `tolerance` of those places, so an edge whose
// clusters moved on (or whose ids were reused after a deletion) is a new edge, tried afresh.
class EdgeMemory {
 public:
  struct Entry {
    int a = -1, b = -1;  // a < b
    Eigen::Vector2d pa = Eigen::Vector2d::Zero(), pb = Eigen::Vector2d::Zero();
  };

  explicit EdgeMemory(double tolerance) : tolerance2_(tolerance * tolerance) {}

  void mark(int a, int b, const Eigen::Vector2d& pa, const Eigen::Vector2d& pb);
  // Whether the edge between a at pa and b at pb is remembered as illegal.
  bool illegal(int a, int b, const Eigen::Vector2d& pa, const Eigen::Vector2d& pb) const;
  std::size_t size() const { return edges_.size(); }
  void clear() { edges_.clear(); }
  std::vector<Entry> entries() const;  // ordered by (a, b)

 private:
  double tolerance2_;
  std::map<std::pair<int, int>, std::pair<Eigen::Vector2d, Eigen::Vector2d>> edges_;
};

}  // namespace amp::nav
