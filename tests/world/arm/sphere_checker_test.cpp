// The sphere checker (collision: spheres, docs/arms.md "Sphere model") against FCL on the same
// spheres: the same verdicts and distances on drawn Panda configurations of the shared
// MotionBenchMaker scenes; every state within a certified share of a segment valid; and rrt-connect's
// paths in the sphere model certified free again on the exact meshes, identical for the same seed.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>


#include "amp/core/counters.hpp"
#include "amp/core/rng.hpp"
#include "amp/roadmap/local_planners/edge_certifier.hpp"
#include "amp/roadmap/run.hpp"
#include "amp/world/arm_environment.hpp"
#include "amp/world/arm_problem.hpp"
#include "support/sphere_test_cache.hpp"
#include "support/source_tree.hpp"

namespace amp::world {
namespace {

namespace fs = std::filesystem;

fs::path panda_dir() { return fs::path(AMP_SOURCE_DIR) / ".." / "shared" / "mbm" / "panda"; }

const ArmDescription& sphere_robot() {
  static const ArmDescription robot = load_arm_description(
      panda_dir() / "panda.urdf", panda_dir() / "panda.srdf", {}, ArmCollisionOptions{ArmCollision::kSpheres, {}, test::shared_sphere_cache()});
  return robot;
}

const ArmDescription& mesh_robot() {
  static const ArmDescription robot = load_arm_description(panda_dir() / "panda.urdf", panda_dir() / "panda.srdf");
  return robot;
}

struct Scene {
  std::string family;
  int number;
  fs::path scene() const { return panda_dir() / "problems" / family / ("scene" + id() + ".yaml"); }
  fs::path request() const { return panda_dir() / "problems" / family / ("request" + id() + ".yaml"); }
  std::string id() const {
    std::string n = std::to_string(number);
    return std::string(4 - n.size(), '0') + n;
  }
};

const std::vector<Scene> kScenes = {{"box", 1}, {"table_pick", 1}, {"bookshelf_small", 1}};

const ArmEnvironment& arm(const Problem& p) { return dynamic_cast<const ArmEnvironment&>(*p.environment); }

TEST(SphereChecker, AgreesWithFclOnTheSameSpheres) {
  for (const Scene& sc : kScenes) {
    const Problem p = load_arm_problem(sphere_robot(), sc.scene(), sc.request());
    ASSERT_TRUE(arm(p).sphere_checked()) << sc.family;
    core::Counters counters;
    const auto fast = p.environment->make_checker(counters);
    const auto fcl = arm(p).make_fcl_checker(counters);
    core::Rng rng(7);
    State s;
    int valid = 0, invalid = 0;
    for (int i = 0; i < 1500; ++i) {
      p.space->sample_uniform(rng, s);
      const double reference = fcl->clearance(s).distance;
      const double measured = fast->clearance(s).distance;
      // FCL's distances between primitives are exact to its tolerance (1e-6 here).
      ASSERT_NEAR(measured, reference, 1e-5) << sc.family << ", state " << i;
      const bool verdict = fcl->is_valid(s);
      if (reference > 1e-5 || !verdict) {
        ASSERT_EQ(fast->is_valid(s), verdict) << sc.family << ", state " << i;
      }
      (verdict ? valid : invalid) += 1;
      if (verdict) {
        ASSERT_NEAR(fast->free_radius(s), fcl->free_radius(s), 1e-5) << sc.family << ", state " << i;
      } else {
        ASSERT_EQ(fast->free_radius(s), 0.0) << sc.family << ", state " << i;
      }
    }
    // Both verdicts occur, so the comparison means something.
    EXPECT_GT(valid, 100) << sc.family;
    EXPECT_GT(invalid, 100) << sc.family;
  }
}

// Every state within the share the sphere checker certifies is valid by FCL's check of the spheres,
// and the share is never below the whole-robot bound (free_radius / motion_bound) it refines.
TEST(SphereChecker, CertifiedShareIsFree) {
  const Problem p = load_arm_problem(sphere_robot(), kScenes[0].scene(), kScenes[0].request());
  core::Counters counters;
  const auto fast = p.environment->make_checker(counters);
  const auto fcl = arm(p).make_fcl_checker(counters);
  core::Rng rng(11);
  State s, b, at;
  int tested = 0;
  for (int i = 0; i < 3000 && tested < 300; ++i) {
    p.space->sample_uniform(rng, s);
    p.space->sample_uniform(rng, b);
    if (!fcl->is_valid(s)) continue;
    ++tested;
    const double share = fast->free_share(s, s, b);
    ASSERT_GE(share, fast->free_radius(s) / fast->motion_bound(s, b) * (1 - 1e-12)) << "state " << i;
    const double reach = std::min(share, 1.0);
    for (int k = 1; k <= 20; ++k) {
      p.space->interpolate(s, b, reach * k / 20.0, at);
      ASSERT_TRUE(fcl->is_valid(at)) << "state " << i << ", " << k << "/20 of share " << share;
    }
  }
  EXPECT_EQ(tested, 300);
}

// rrt-connect in the sphere model: solved, joins the request's start and goal, certified free on the
// exact meshes edge by edge (EdgeCertifier over FCL on the URDF's meshes), and the same path again
// for the same seed.
TEST(SphereChecker, PathsAreFreeOnTheMeshes) {
  for (const Scene& sc : kScenes) {
    const Problem spheres = load_arm_problem(sphere_robot(), sc.scene(), sc.request());
    const Problem meshes = load_arm_problem(mesh_robot(), sc.scene(), sc.request());
    const roadmap::RunOutcome run = roadmap::execute_run(spheres, "rrt-connect", {}, 1, 30.0, std::nullopt);
    ASSERT_EQ(run.record.status, core::PlanStatus::kSolved) << sc.family;
    ASSERT_GE(run.path.size(), 2u);
    EXPECT_TRUE(run.path.front() == spheres.start()) << sc.family;
    EXPECT_TRUE(run.path.back() == spheres.goal()) << sc.family;
    core::Counters counters;
    const auto exact = meshes.environment->make_checker(counters);
    roadmap::EdgeCertifier certifier(*meshes.space, *exact);
    for (std::size_t i = 1; i < run.path.size(); ++i) {
      ASSERT_TRUE(exact->is_valid(run.path[i])) << sc.family << ", state " << i;
      ASSERT_TRUE(certifier.certify(run.path[i - 1], run.path[i])) << sc.family << ", edge " << i;
    }
    const roadmap::RunOutcome again = roadmap::execute_run(spheres, "rrt-connect", {}, 1, 30.0, std::nullopt);
    ASSERT_EQ(again.path.size(), run.path.size()) << sc.family;
    for (std::size_t i = 0; i < run.path.size(); ++i) EXPECT_TRUE(again.path[i] == run.path[i]) << sc.family << ", state " << i;
  }
}

}  // namespace
}  // namespace amp::world
