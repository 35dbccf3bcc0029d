#pragma once
#include <cstddef>

#include <Eigen/Core>

#include "amp/core/counters.hpp"
#include "amp/core/state.hpp"

namespace amp::world {

// Result of a clearance query: distance from the robot to the nearest obstacle and the two closest
// points (world frame; z = 0 for planar worlds). distance <= 0 when in collision (penetration depth
// is not computed: the value is 0).
struct Clearance {
  double distance = 0.0;
  Eigen::Vector3d robot_point = Eigen::Vector3d::Zero();
  Eigen::Vector3d obstacle_point = Eigen::Vector3d::Zero();
};

// Answers "is this configuration free?" and "how far is the nearest obstacle?". Every call is
// counted in the run's Counters (CD calls are the papers' cost measure), hence the non-virtual
// public functions around the private virtual ones. One checker per thread: implementations keep
// scratch buffers so that a check never allocates; the world they read is shared and immutable.
class ValidityChecker {
 public:
  explicit ValidityChecker(core::Counters& counters) : counters_(&counters) {}
  virtual ~ValidityChecker() = default;
  ValidityChecker(const ValidityChecker&) = delete;
  ValidityChecker& operator=(const ValidityChecker&) = delete;

  // Free of obstacles, of self-collision and inside the workspace. Counts one CD call.
  bool is_valid(const State& s) const {
    counters_->add_cd_call();
    return check(s);
  }
  // How many states all_valid takes at once: 1 for a checker that checks one state at a time (the
  // default); the sphere checker poses a block of configurations together in SIMD lanes, as VAMP
  // does (docs/arms.md, "Sphere model").
  std::size_t block_size() const { return compute_block_size(); }
  // Whether every one of states[0..n) is valid, 1 <= n <= block_size(); the same verdict as
  // is_valid on each. Counts n CD calls: a block is checked whole.
  bool all_valid(const State* const* states, std::size_t n) const {
    for (std::size_t i = 0; i < n; ++i) counters_->add_cd_call();
    return check_block(states, n);
  }
  // Distance to the nearest obstacle. Counts one clearance call (not a CD call).
  Clearance clearance(const State& s) const {
    counters_->add_clearance_call();
    return compute_clearance(s);
  }

  // Edge certification (roadmap::EdgeCertifier). A distance r such that every placement of the
  // robot in which no robot point is more than r from where it is at s is valid: obstacles,
  // workspace bounds and self-collision (which needs half the distance between two links, as
  // both may move). 0 when s is not valid. Counts one clearance call (not a CD call).
  double free_radius(const State& s) const {
    counters_->add_clearance_call();
    return compute_free_radius(s);
  }
  // An upper bound on the distance any robot point travels while the state follows the space's
  // interpolation from a to b (t from 0 to 1). Pure geometry: counts nothing.
  double motion_bound(const State& a, const State& b) const { return compute_motion_bound(a, b); }
  // The share of the segment from a to b (its parameter t, from 0 to 1) that the state may move
  // from s, forward or back along the segment's direction, staying valid: what edge certification
  // steps by. By default free_radius(s) / motion_bound(a, b); a checker that knows which of its
  // parts moves how much per joint (arms) weighs each distance it measures against that part's own
  // motion, which is never less. 0 when s is not valid; motion_bound(a, b) must be positive. Counts
  // one clearance call.
  double free_share(const State& s, const State& a, const State& b) const {
    counters_->add_clearance_call();
    return compute_free_share(s, a, b);
  }

  core::Counters& counters() const { return *counters_; }

 private:
  virtual bool check(const State& s) const = 0;
  virtual Clearance compute_clearance(const State& s) const = 0;
  virtual double compute_free_radius(const State& s) const = 0;
  virtual double compute_motion_bound(const State& a, const State& b) const = 0;
  virtual std::size_t compute_block_size() const { return 1; }
  virtual bool check_block(const State* const* states, std::size_t n) const {
    for (std::size_t i = 0; i < n; ++i) {
      if (!check(*states[i])) return false;
    }
    return true;
  }
  virtual double compute_free_share(const State& s, const State& a, const State& b) const {
    return compute_free_radius(s) / compute_motion_bound(a, b);
  }

  core::Counters* counters_;
};

}  // namespace amp::world
