#pragma once
// Private: the ValidityChecker of an ArmEnvironment whose robot is made of spheres (a sphere model,
// amp/world/arm_spheres.hpp) in a scene of primitives. Exact sphere distances replace FCL: a link's
// bounding sphere first (the coarse level), its spheres only where that one is close.
#include <memory>
#include <vector>

#include "amp/world/arm_environment.hpp"
#include "amp/world/validity_checker.hpp"

namespace amp::world::detail {

struct SphereKernels;

// Whether an environment can use SphereChecker: every robot part a sphere, every obstacle a primitive.
bool sphere_checker_applies(const ArmEnvironment& env);

class SphereChecker final : public ValidityChecker {
 public:
  SphereChecker(const ArmEnvironment& env, core::Counters& counters, const SphereKernels& kernels);
  ~SphereChecker() override;

 private:
  struct Model;
  struct Scratch;
  bool check(const State& s) const override;
  std::size_t compute_block_size() const override;
  bool check_block(const State* const* states, std::size_t n) const override;
  Clearance compute_clearance(const State& s) const override;
  double compute_free_radius(const State& s) const override;
  double compute_motion_bound(const State& a, const State& b) const override;
  double compute_free_share(const State& s, const State& a, const State& b) const override;

  // Poses the links and their bounding spheres in each lane (states[0..n), the rest repeating the
  // last); a link's spheres in a lane are placed when first asked for. place(s) is a block of one.
  void place_block(const State* const* states, std::size_t n) const;
  void place_one(const State& s) const;
  void place(const State& s) const;
  // The link's block of world x (then y, z at stride) in `lane`.
  const double* placed(std::size_t link, std::size_t lane = 0) const;
  const double* joint_steps(const State& a, const State& b) const;
  // Whether lanes [0, n) are free of the scene, and of self-collision.
  bool scene_free(std::size_t n) const;
  bool self_free(std::size_t n) const;
  // free_share's halves: each lowers `share`; false when the state is not valid.
  bool scene_share(const double* steps, double& share) const;
  bool self_share(const double* steps, double& share) const;
  // The least clearance of link l's spheres to the scene, if below `below` (else `below`).
  double link_clearance(std::size_t l, double below) const;

  const ArmEnvironment& env_;
  std::shared_ptr<const Model> model_;
  std::unique_ptr<Scratch> scratch_;
};

}  // namespace amp::world::detail
