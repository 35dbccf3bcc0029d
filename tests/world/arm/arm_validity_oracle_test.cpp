// AMP's arm validity (load_arm_problem + make_checker + is_valid) against an independent check on
// MotionBenchMaker's Panda problems (../shared/mbm): for each scene family, 10,000 seeded random
// configurations within the joint limits, 100 per scene file, must get the same answer from both.
//
// The independent check (mesh_oracle.hpp) shares no code with AMP's arm loaders or checker: urdfdom,
// KDL, assimp, yaml-cpp, tinyxml2 and FCL called directly. (The shared scenes'
// matrices allow exactly the SRDF's disabled pairs; two_link_arm_test.cpp covers pairs that only a
// scene allows, link-link and link-object.)
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "amp/core/counters.hpp"
#include "amp/core/joint_space.hpp"
#include "amp/core/rng.hpp"
#include "amp/world/arm_problem.hpp"
#include "support/sanitizer_build.hpp"
#include "world/arm/mesh_oracle.hpp"

namespace amp::world {
namespace {

namespace fs = std::filesystem;

constexpr int kScenesPerFamily = 100;
// Under the sanitizers a quarter of them (support/sanitizer_build.hpp).
constexpr int kConfigurationsPerScene = test::case_share(100);
constexpr std::uint64_t kSeed = 35;
constexpr int kReportedDisagreements = 10;

fs::path panda_dir() { return test::mbm_panda_dir(); }

// A seed stream per family (FNV-1a of its name), so that the families draw different configurations.
std::uint64_t family_stream(const std::string& name) {
  std::uint64_t h = 1469598103934665603ULL;
  for (const char c : name) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ULL;
  return h;
}

class ArmValidityOracle : public ::testing::TestWithParam<const char*> {};

TEST_P(ArmValidityOracle, IsValidEqualsIndependentCheck) {
  const fs::path family = panda_dir() / "problems" / GetParam();
  if (!fs::is_directory(family) || !fs::is_regular_file(panda_dir() / "panda.urdf")) {
    GTEST_SKIP() << family << " is absent (the shared test data, ../shared/mbm beside the source tree)";
  }
  const auto started = std::chrono::steady_clock::now();
  const test::OracleRobot oracle(panda_dir() / "panda.urdf", panda_dir() / "panda.srdf");
  const auto& fk_joints = oracle.fk->joints();

  int agree = 0, disagree = 0, invalid = 0, self_contacts = 0;
  double loading = 0.0;  // seconds in load_arm_problem
  // The robot is read once, as `amp bench` reads a folder's: the single-file path loads it per problem.
  const ArmDescription robot = load_arm_description(panda_dir() / "panda.urdf", panda_dir() / "panda.srdf");
  for (int i = 1; i <= kScenesPerFamily; ++i) {
    const ArmFiles files{panda_dir() / "panda.urdf", panda_dir() / "panda.srdf", family / ("scene" + test::scene_number(i) + ".yaml"),
                         family / ("request" + test::scene_number(i) + ".yaml"), {}, {}};
    const auto load_started = std::chrono::steady_clock::now();
    const Problem problem = load_arm_problem(robot, files.scene, files.request);
    loading += std::chrono::duration<double>(std::chrono::steady_clock::now() - load_started).count();
    core::Counters counters;
    const auto checker = problem.environment->make_checker(counters);
    const test::OracleScene scene(files.scene);
    const test::OracleCheck check(oracle, scene);

    // Joints outside the group at their start values (the Panda's finger joints are fixed anyway);
    // the group's joints, named by the problem's space, drawn within the limits urdfdom reads.
    const auto& space = dynamic_cast<const core::JointSpace&>(*problem.space);
    const std::map<std::string, double> start = test::request_start(files.request);
    std::vector<double> values(fk_joints.size(), 0.0);
    for (std::size_t k = 0; k < fk_joints.size(); ++k) {
      if (start.count(fk_joints[k]) > 0) values[k] = start.at(fk_joints[k]);
    }
    std::vector<int> slot;  // state coordinate -> fk joint
    for (const core::Joint& j : space.joints()) {
      slot.push_back(oracle.fk->joint_index(j.name));
      ASSERT_GE(slot.back(), 0) << j.name << " is not a movable joint on KDL's chains";
    }
    core::Rng rng(core::derive_seed(core::derive_seed(kSeed, family_stream(GetParam())), static_cast<std::uint64_t>(i)));
    for (int n = 0; n < kConfigurationsPerScene; ++n) {
      State q(space.dimension());
      for (int k = 0; k < space.dimension(); ++k) {
        const urdf::JointLimitsSharedPtr limits = oracle.urdf->getJoint(space.joints()[static_cast<std::size_t>(k)].name)->limits;
        q[k] = rng.uniform(limits->lower, limits->upper);
        values[static_cast<std::size_t>(slot[static_cast<std::size_t>(k)])] = q[k];
      }
      const bool amp_valid = checker->is_valid(q);
      const test::Verdict verdict = check.check(values);
      if (!verdict.valid) {
        ++invalid;
        if (verdict.contact.rfind("links", 0) == 0) ++self_contacts;
      }
      if (amp_valid == verdict.valid) {
        ++agree;
      } else if (++disagree <= kReportedDisagreements) {
        ADD_FAILURE() << files.scene.filename() << " configuration " << n << " (" << q.transpose() << "): AMP says "
                      << (amp_valid ? "valid" : "invalid") << ", the independent check "
                      << (verdict.valid ? "valid" : "invalid: " + verdict.contact);
      }
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  const int total = kScenesPerFamily * kConfigurationsPerScene;
  std::cout << "[ figures  ] " << GetParam() << ": " << agree << " of " << total << " configurations agree (" << disagree
            << " disagree); " << invalid << " invalid by the independent check (" << self_contacts << " first found as self-collision), "
            << total - invalid << " valid; " << seconds << " s, of which " << loading << " s in load_arm_problem\n";
  EXPECT_EQ(disagree, 0);
  EXPECT_EQ(agree, total);
  // Both answers occur, so that agreement means something.
  EXPECT_GT(invalid, 0);
  EXPECT_LT(invalid, total);
}

INSTANTIATE_TEST_SUITE_P(MotionBenchMaker, ArmValidityOracle, ::testing::Values("box", "table_pick", "bookshelf_small"));

}  // namespace
}  // namespace amp::world
