// OMPL 1.5 + FCL, reading each OMPL.app `.cfg` problem as OMPL.app does, is the oracle for AMP's
// reading of it: the same states must be valid, and OMPL.app's own reference solutions must be
// valid in AMP. A loader that disagrees with OMPL answers a different problem than the benchmark's.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "amp/core/counters.hpp"
#include "amp/core/path_file.hpp"
#include "amp/world/problem.hpp"
#include "ompl_app_problem.hpp"
#include "oracle_cases.hpp"

namespace amp::oracle {
namespace {

namespace fs = std::filesystem;

std::string box_string(const Eigen::AlignedBox3d& b) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "[%.6g %.6g %.6g] .. [%.6g %.6g %.6g]", b.min().x(), b.min().y(), b.min().z(),
                b.max().x(), b.max().y(), b.max().z());
  return buf;
}

std::string ompl_verdict(const OmplAppProblem& p, const State& s) {
  if (!p.in_bounds(s)) return "invalid (out of bounds)";
  return p.is_valid(s) ? "valid" : "invalid (contact)";
}

std::string amp_verdict(const world::Problem& p, const world::ValidityChecker& c, const State& s) {
  const bool ok = c.is_valid(s);
  return std::string(ok ? "valid" : "invalid") + (p.space->in_bounds(s) ? "" : " (outside AMP's space)");
}

class CfgOracle : public ::testing::TestWithParam<CfgCase> {
 protected:
  void SetUp() override {
    if (!fs::is_regular_file(GetParam().file)) GTEST_SKIP() << GetParam().file << " is absent (the shared test data, ../shared beside the source tree)";
  }
};

// OMPL's view of the problem, printed beside AMP's so that a loader difference shows at a glance;
// start and goal must be free for OMPL (else the oracle itself misreads the file) and AMP must place
// them at the same poses.
TEST_P(CfgOracle, OmplViewOfStartGoalAndBounds) {
  const OmplAppProblem ompl(GetParam().file);
  const auto& si = *ompl.si();
  std::printf("OMPL view of %s (%s)\n", GetParam().file.c_str(), ompl.is_3d() ? "SE3" : "SE2");
  std::printf("  volume (reference point): %s\n", box_string(ompl.volume()).c_str());
  std::printf("  robot: %zu triangles, shifted by (%.6g %.6g %.6g), box in its frame %s\n", ompl.robot_triangles(),
              ompl.robot_shift().x(), ompl.robot_shift().y(), ompl.robot_shift().z(),
              box_string(ompl.robot_box()).c_str());
  std::printf("  world: %zu triangles, box %s\n", ompl.world_triangles(), box_string(ompl.world_box()).c_str());
  std::printf("  resolution: %g of maximum extent %.6g = %.6g\n", si.getStateValidityCheckingResolution(),
              si.getMaximumExtent(), si.getStateSpace()->getLongestValidSegmentLength());
  std::printf("  start %s: %s\n  goal  %s: %s\n", to_string(ompl.start()).c_str(),
              ompl_verdict(ompl, ompl.start()).c_str(), to_string(ompl.goal()).c_str(),
              ompl_verdict(ompl, ompl.goal()).c_str());
  EXPECT_TRUE(ompl.is_valid(ompl.start())) << "OMPL finds the start invalid";
  EXPECT_TRUE(ompl.is_valid(ompl.goal())) << "OMPL finds the goal invalid";

  world::Problem amp;
  ASSERT_NO_THROW(amp = world::load_problem(GetParam().file));
  core::Counters counters;
  const auto checker = amp.environment->make_checker(counters);
  std::printf("AMP view: space %s, resolution %.6g, maximum extent %.6g\n", std::string(amp.space->kind()).c_str(),
              amp.space->resolution(), amp.space->maximum_extent());
  std::printf("  workspace %s, robot radius %.6g\n", box_string(amp.environment->workspace_bounds()).c_str(),
              amp.environment->robot_radius());
  std::printf("  start %s: %s\n  goal  %s: %s\n", to_string(amp.start()).c_str(),
              amp_verdict(amp, *checker, amp.start()).c_str(), to_string(amp.goal()).c_str(),
              amp_verdict(amp, *checker, amp.goal()).c_str());
  EXPECT_EQ(amp.space->kind(), ompl.is_3d() ? "se3" : "se2");
  EXPECT_TRUE(same_pose(amp.start(), ompl.start())) << "AMP " << to_string(amp.start()) << " vs OMPL "
                                                    << to_string(ompl.start());
  EXPECT_TRUE(same_pose(amp.goal(), ompl.goal())) << "AMP " << to_string(amp.goal()) << " vs OMPL "
                                                  << to_string(ompl.goal());
}

// 10,000 states uniform in OMPL's space (fixed seed): AMP and OMPL agree on >= 99.9 % of them; the
// slack is for contacts within rounding of a surface, which two exact checkers may call differently.
TEST_P(CfgOracle, ValidityAgreesWithOmplOnUniformStates) {
  constexpr int kStates = 10000;
  const OmplAppProblem ompl(GetParam().file);
  world::Problem amp;
  ASSERT_NO_THROW(amp = world::load_problem(GetParam().file));
  core::Counters counters;
  const auto checker = amp.environment->make_checker(counters);

  std::mt19937_64 rng(0x0A11CE5EEDULL);
  int agree = 0, ompl_free = 0, amp_free = 0;
  for (int i = 0; i < kStates; ++i) {
    const State s = ompl.uniform_state(rng);
    const bool o = ompl.is_valid(s), a = checker->is_valid(s);
    ompl_free += o;
    amp_free += a;
    if (o == a) {
      ++agree;
    } else {
      std::printf("disagreement #%d at %s: OMPL %s, AMP %s\n", i, to_string(s).c_str(), ompl_verdict(ompl, s).c_str(),
                  amp_verdict(amp, *checker, s).c_str());
    }
  }
  std::printf("%s: agreement %.2f %% (%d/%d); free: OMPL %.2f %%, AMP %.2f %%\n", GetParam().name.c_str(),
              100.0 * agree / kStates, agree, kStates, 100.0 * ompl_free / kStates, 100.0 * amp_free / kStates);
  RecordProperty("agreement_percent", std::to_string(100.0 * agree / kStates));
  EXPECT_GE(agree, kStates - kStates / 1000);
  // A world that never touches the robot is no planning problem: typically meshes that lie outside
  // the robot's plane (a planar problem read with another up axis than its author meant).
  EXPECT_LT(ompl_free, kStates) << "OMPL finds every state free: no obstacle is within the robot's reach";
}

// OMPL.app's reference solution `<stem>.path`: AMP reads it, and finds every state and every
// segment (at AMP's own resolution) valid. OMPL must accept it first, or the oracle is wrong.
TEST_P(CfgOracle, ReferencePathIsValidInAmp) {
  const fs::path ref = reference_path_of(GetParam().file);
  if (ref.empty()) GTEST_SKIP() << "no reference path beside " << GetParam().file;
  const OmplAppProblem ompl(GetParam().file);
  const std::vector<State> path = read_ompl_path(ref, ompl.is_3d());
  ASSERT_GE(path.size(), 2u);
  for (std::size_t i = 0; i < path.size(); ++i) {
    ASSERT_TRUE(ompl.is_valid(path[i])) << "oracle: OMPL rejects its own state " << i;
    if (i > 0) {
      ASSERT_TRUE(ompl.check_motion(path[i - 1], path[i])) << "oracle: OMPL rejects segment " << i - 1;
    }
  }

  world::Problem amp;
  ASSERT_NO_THROW(amp = world::load_problem(GetParam().file));
  std::vector<State> read;
  EXPECT_NO_THROW(read = core::read_path_file(ref, *amp.space));
  EXPECT_EQ(read.size(), path.size());
  for (std::size_t i = 0; i < std::min(read.size(), path.size()); ++i) {
    EXPECT_TRUE(same_pose(read[i], path[i], 1e-6)) << "state " << i << ": AMP read " << to_string(read[i]);
  }

  core::Counters counters;
  const auto checker = amp.environment->make_checker(counters);
  int bad_states = 0, bad_segments = 0;
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (!checker->is_valid(path[i])) {
      ++bad_states;
      std::printf("reference state %zu %s: OMPL valid, AMP %s\n", i, to_string(path[i]).c_str(),
                  amp_verdict(amp, *checker, path[i]).c_str());
    }
  }
  const core::Space& space = *amp.space;
  State q;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const int steps = std::max(1, static_cast<int>(std::ceil(space.distance(path[i], path[i + 1]) / space.resolution())));
    for (int k = 1; k < steps; ++k) {
      space.interpolate(path[i], path[i + 1], static_cast<double>(k) / steps, q);
      if (!checker->is_valid(q)) {
        ++bad_segments;
        std::printf("reference segment %zu -> %zu invalid in AMP at t = %d/%d, %s\n", i, i + 1, k, steps,
                    to_string(q).c_str());
        break;
      }
    }
  }
  std::printf("%s: reference path %zu states, AMP rejects %d states and %d of %zu segments\n", GetParam().name.c_str(),
              path.size(), bad_states, bad_segments, path.size() - 1);
  EXPECT_EQ(bad_states, 0);
  EXPECT_EQ(bad_segments, 0);
}

INSTANTIATE_TEST_SUITE_P(Cfg, CfgOracle, ::testing::ValuesIn(cfg_cases()),
                         [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace amp::oracle
