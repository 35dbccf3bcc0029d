#pragma once
// An OMPL.app `.cfg` problem read the way OMPL.app reads it, on OMPL 1.5's public API with an FCL
// validity checker: the oracle that AMP's own `.cfg` loader is compared against. It shares no code
// with AMP's loader on purpose; only the State layout (SE2 x y θ, SE3 x y z qx qy qz qw) is common.
#include <filesystem>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <ompl/base/SpaceInformation.h>

#include "amp/core/state.hpp"

namespace amp::oracle {

class OmplAppProblem {
 public:
  // Throws std::runtime_error on a missing key or an unreadable mesh.
  explicit OmplAppProblem(const std::filesystem::path& cfg);
  ~OmplAppProblem();
  OmplAppProblem(const OmplAppProblem&) = delete;
  OmplAppProblem& operator=(const OmplAppProblem&) = delete;

  // SE3 when the cfg gives start.z, otherwise SE2 (as OMPL.app's benchmark reader decides).
  bool is_3d() const { return is_3d_; }
  // Set up (si->setup() done): checker, default motion validator, default resolution.
  const ompl::base::SpaceInformationPtr& si() const { return si_; }

  const State& start() const { return start_; }
  const State& goal() const { return goal_; }

  // OMPL + FCL's verdict: inside the bounds (reference point only) and no contact.
  bool is_valid(const State& s) const;
  // Inside the OMPL space's bounds (SE2 yaw in [-π, π], SE3 |q| = 1 within 1e-9).
  bool in_bounds(const State& s) const;
  // OMPL's DiscreteMotionValidator on a -> b (b's validity included, as OMPL does); when it fails,
  // `last_valid_t` (if given) is the fraction of the segment up to its last valid state.
  bool check_motion(const State& a, const State& b, double* last_valid_t = nullptr) const;
  // OMPL's interpolation, for printing where a segment fails.
  State interpolate(const State& a, const State& b, double t) const;
  // A state uniform in the OMPL space: position in the volume, yaw in [-π, π) or a uniform unit
  // quaternion (Shoemake), drawn with our own portable map from 53-bit uniforms.
  State uniform_state(std::mt19937_64& rng) const;

  // What OMPL's view prints: volume bounds (z 0..0 for 2-D), the shift applied to the robot mesh
  // (mean of its vertices; z kept for 2-D), the robot's box in its own frame and the world's box.
  Eigen::AlignedBox3d volume() const { return volume_; }
  const Eigen::Vector3d& robot_shift() const { return robot_shift_; }
  const Eigen::AlignedBox3d& robot_box() const { return robot_box_; }
  const Eigen::AlignedBox3d& world_box() const { return world_box_; }
  std::size_t robot_triangles() const { return robot_triangles_; }
  std::size_t world_triangles() const { return world_triangles_; }

  // The `[problem]` keys of the file.
  const std::map<std::string, std::string>& keys() const { return keys_; }

 private:
  void to_ompl(const State& s, ompl::base::State* out) const;
  State from_ompl(const ompl::base::State* s) const;

  bool is_3d_ = false;
  std::map<std::string, std::string> keys_;
  Eigen::AlignedBox3d volume_;
  Eigen::Vector3d robot_shift_ = Eigen::Vector3d::Zero();
  Eigen::AlignedBox3d robot_box_, world_box_;
  std::size_t robot_triangles_ = 0, world_triangles_ = 0;
  State start_, goal_;
  ompl::base::SpaceInformationPtr si_;
};

// The same pose: positions within `tol`, SE2 yaws equal modulo 2π, SE3 quaternions q and -q alike.
bool same_pose(const State& a, const State& b, double tol = 1e-9);

// Reads an OMPL.app `.path` (one state per line) into AMP's layout; SE3 quaternions normalised.
// Throws std::runtime_error on a line with the wrong number of values.
std::vector<State> read_ompl_path(const std::filesystem::path& file, bool is_3d);

// "(x, y, θ)" or "(x, y, z, qx, qy, qz, qw)" with enough digits to reproduce the state.
std::string to_string(const State& s);

}  // namespace amp::oracle
