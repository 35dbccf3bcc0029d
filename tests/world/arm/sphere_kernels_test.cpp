// The sphere checker's two builds of its SIMD kernels (ArmEnvironment::SphereIsa): the baseline and
// the AVX2 build give the same answers bit for bit (both are compiled with -ffp-contract=off) on
// drawn Panda configurations and segments of the shared MotionBenchMaker scenes; the build chosen
// for this CPU is the one it can run; and only a robot of spheres gets a sphere checker.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include "amp/core/counters.hpp"
#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"
#include "amp/world/arm_environment.hpp"
#include "amp/world/arm_problem.hpp"
#include "support/sphere_test_cache.hpp"
#include "support/source_tree.hpp"

namespace amp::world {
namespace {

namespace fs = std::filesystem;
using Isa = ArmEnvironment::SphereIsa;

constexpr int kStates = 2000;

bool cpu_has_avx2() {
#if defined(__x86_64__) || defined(__i386__)
  return __builtin_cpu_supports("avx2") != 0;
#else
  return false;
#endif
}

fs::path panda_dir() { return fs::path(AMP_SOURCE_DIR) / ".." / "shared" / "mbm" / "panda"; }

const ArmDescription& sphere_robot() {
  static const ArmDescription robot = load_arm_description(
      panda_dir() / "panda.urdf", panda_dir() / "panda.srdf", {}, ArmCollisionOptions{ArmCollision::kSpheres, {}, test::shared_sphere_cache()});
  return robot;
}

fs::path scene_file(const std::string& family, const char* kind) {
  return panda_dir() / "problems" / family / (std::string(kind) + "0001.yaml");
}

const std::vector<std::string> kFamilies = {"box", "table_pick", "bookshelf_small"};

const ArmEnvironment& arm(const Problem& p) { return dynamic_cast<const ArmEnvironment&>(*p.environment); }

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

TEST(SphereKernels, InUseIsTheCpusBest) {
  EXPECT_STREQ(ArmEnvironment::sphere_kernels_in_use(), cpu_has_avx2() ? "avx2" : "baseline");
}

// Every answer of the AVX2 build equals the baseline's bit for bit: verdicts, clearance distances,
// free radii and certified shares, on valid and invalid states alike.
TEST(SphereKernels, Avx2BuildEqualsBaselineBitForBit) {
  if (!cpu_has_avx2()) GTEST_SKIP() << "this CPU lacks AVX2: the avx2 build cannot run here";
  for (const std::string& family : kFamilies) {
    const Problem p = load_arm_problem(sphere_robot(), scene_file(family, "scene"), scene_file(family, "request"));
    ASSERT_TRUE(arm(p).sphere_checked()) << family;
    core::Counters counters;
    const auto baseline = arm(p).make_sphere_checker(counters, Isa::kBaseline);
    const auto avx2 = arm(p).make_sphere_checker(counters, Isa::kAvx2);
    core::Rng rng(23);
    State s, b;
    int valid = 0, invalid = 0, positive_share = 0;
    for (int i = 0; i < kStates; ++i) {
      p.space->sample_uniform(rng, s);
      p.space->sample_uniform(rng, b);
      const bool verdict = baseline->is_valid(s);
      ASSERT_EQ(avx2->is_valid(s), verdict) << family << ", state " << i;
      (verdict ? valid : invalid) += 1;
      const double clearance = baseline->clearance(s).distance;
      ASSERT_EQ(bits(avx2->clearance(s).distance), bits(clearance))
          << family << ", state " << i << ": " << avx2->clearance(s).distance << " vs " << clearance;
      const double radius = baseline->free_radius(s);
      ASSERT_EQ(bits(avx2->free_radius(s)), bits(radius))
          << family << ", state " << i << ": " << avx2->free_radius(s) << " vs " << radius;
      const double share = baseline->free_share(s, s, b);
      ASSERT_EQ(bits(avx2->free_share(s, s, b)), bits(share))
          << family << ", state " << i << ": " << avx2->free_share(s, s, b) << " vs " << share;
      if (share > 0.0) ++positive_share;
    }
    // Both verdicts, and non-trivial shares, occur: the comparison covers the kernels' real work.
    EXPECT_GT(valid, kStates / 20) << family;
    EXPECT_GT(invalid, kStates / 20) << family;
    EXPECT_GT(positive_share, kStates / 20) << family;
  }
}

// kAuto is the build in use: its answers equal that build's.
TEST(SphereKernels, AutoEqualsTheBuildInUse) {
  const Problem p = load_arm_problem(sphere_robot(), scene_file("box", "scene"), scene_file("box", "request"));
  core::Counters counters;
  const auto chosen = arm(p).make_sphere_checker(counters, Isa::kAuto);
  const auto in_use = arm(p).make_sphere_checker(
      counters, std::string(ArmEnvironment::sphere_kernels_in_use()) == "avx2" ? Isa::kAvx2 : Isa::kBaseline);
  const auto plain = p.environment->make_checker(counters);
  core::Rng rng(5);
  State s, b;
  for (int i = 0; i < 200; ++i) {
    p.space->sample_uniform(rng, s);
    p.space->sample_uniform(rng, b);
    ASSERT_EQ(bits(chosen->free_share(s, s, b)), bits(in_use->free_share(s, s, b))) << "state " << i;
    ASSERT_EQ(bits(plain->clearance(s).distance), bits(in_use->clearance(s).distance)) << "state " << i;
  }
}

TEST(SphereKernels, MeshesProblemHasNoSphereChecker) {
  const ArmDescription meshes = load_arm_description(panda_dir() / "panda.urdf", panda_dir() / "panda.srdf");
  const Problem p = load_arm_problem(meshes, scene_file("box", "scene"), scene_file("box", "request"));
  ASSERT_FALSE(arm(p).sphere_checked());
  core::Counters counters;
  EXPECT_THROW(arm(p).make_sphere_checker(counters, Isa::kBaseline), ParameterError);
  EXPECT_THROW(arm(p).make_sphere_checker(counters, Isa::kAvx2), ParameterError);
  EXPECT_THROW(arm(p).make_sphere_checker(counters, Isa::kAuto), ParameterError);
}

}  // namespace
}  // namespace amp::world
