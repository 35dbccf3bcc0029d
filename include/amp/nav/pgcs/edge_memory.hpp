#pragma once
#include <cstddef>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace amp::nav {

// The graph edges a robot found blocked (Vlassis et al.'s "legal-illegal" map connections), kept
// across queries. An edge is named by its clusters' ids and remembered with where its ends were:
// its record holds while both ends are within `tolerance` of those places, so an edge whose
// clusters moved on (or whose ids were reused after a deletion) is a new edge, tried afresh.
// An edge is illegal after `strikes` blocks (1: the paper, at the first); before that it is a
// suspect, which a planner may still use as a last resort (a leg that clipped a door frame is
// blocked without its edge being illegal).
class EdgeMemory {
 public:
  struct Entry {
    int a = -1, b = -1;  // a < b
    Eigen::Vector2d pa = Eigen::Vector2d::Zero(), pb = Eigen::Vector2d::Zero();
    int blocks = 0;  // illegal when >= strikes(), else a suspect
  };

  explicit EdgeMemory(double tolerance, int strikes = 1) : tolerance2_(tolerance * tolerance), strikes_(strikes) {}

  // One more block of the edge between a at pa and b at pb (the first, if its ends moved).
  void mark(int a, int b, const Eigen::Vector2d& pa, const Eigen::Vector2d& pb);
  // Blocks on record for the edge as it stands (0: none).
  int blocks(int a, int b, const Eigen::Vector2d& pa, const Eigen::Vector2d& pb) const {
    return touches(a) && touches(b) ? recorded_blocks(a, b, pa, pb) : 0;
  }
  bool illegal(int a, int b, const Eigen::Vector2d& pa, const Eigen::Vector2d& pb) const {
    return blocks(a, b, pa, pb) >= strikes_;
  }
  int strikes() const { return strikes_; }
  bool empty() const { return edges_.empty(); }
  std::size_t size() const;             // illegal edges
  std::size_t suspects() const;         // edges blocked, not yet illegal
  std::vector<Entry> entries() const;   // every edge blocked, illegal or suspect, ordered by (a, b)
  void clear() {
    edges_.clear();
    touched_.clear();
  }

 private:
  struct Record {
    Eigen::Vector2d pa, pb;
    int blocks = 0;
  };
  double tolerance2_;
  int strikes_;
  std::map<std::pair<int, int>, Record> edges_;
  // Cluster id -> an edge of it is on record: most lookups (a planner asks for every edge it
  // relaxes) are answered without the map.
  std::vector<std::uint8_t> touched_;
  int recorded_blocks(int a, int b, const Eigen::Vector2d& pa, const Eigen::Vector2d& pb) const;
  bool touches(int id) const {
    return id < 0 || (static_cast<std::size_t>(id) < touched_.size() && touched_[static_cast<std::size_t>(id)] != 0);
  }
};

}  // namespace amp::nav
