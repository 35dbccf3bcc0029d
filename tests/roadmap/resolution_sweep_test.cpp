// `resolution` from 1e-1 down to 1e-12 on a small YAML problem whose straight line crosses a box:
// every decade either is refused at load with a one-line FileError naming the field, or runs to a
// valid path or to its limit, within its time limit plus the allowance and never past its node
// limit. (A 1e-10 resolution once wrapped an int step count and returned the straight line
// through the box after 2 CD calls; 1e-9 ran 53 s past its limit inside one edge.)
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "amp/core/edge_steps.hpp"
#include "amp/core/error.hpp"
#include "amp/roadmap/run.hpp"
#include "amp/world/problem.hpp"
#include "support/path_checks.hpp"
#include "support/time_allowance.hpp"

namespace amp::roadmap {
namespace {

namespace fs = std::filesystem;

constexpr double kTimeLimit = 0.5;
constexpr std::size_t kNodeLimit = 2000;
constexpr double kAllowance = test::time_allowance(kTimeLimit);
// Paths are re-checked against the same world at this resolution (4 times finer): checking at a
// 1e-9 step would cost as much as planning did.
constexpr double kCheckResolution = 1e-2;

// The straight line (1,1) -> (9,9) runs through the middle of the box.
std::string problem_text(double resolution) {
  char r[32];
  std::snprintf(r, sizeof r, "%.0e", resolution);
  return std::string("name: Sweep\n"
                     "bounds: {min: [0, 0], max: [10, 10]}\n"
                     "resolution: ") +
         r +
         "\n"
         "world:\n"
         "  obstacles:\n"
         "    - {rectangle: {center: [5, 5], size: [2, 4]}}\n"
         "robot: {type: disc, radius: 0.3}\n"
         "start: [1, 1]\n"
         "goal: [9, 9]\n";
}

class ResolutionSweep : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("amp_resolution_sweep_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  fs::path write(double resolution, const std::string& name) const {
    const fs::path file = dir_ / name;
    std::ofstream(file) << problem_text(resolution);
    return file;
  }
  fs::path dir_;
};

void sweep(const fs::path& dir, const std::string& planner, const fs::path& reference_file) {
  const world::Problem reference = world::load_problem(reference_file);
  for (int decade = 1; decade <= 12; ++decade) {
    const double resolution = std::pow(10.0, -decade);
    SCOPED_TRACE(planner + " at resolution 1e-" + std::to_string(decade));
    const fs::path file = dir / ("sweep_" + std::to_string(decade) + ".yaml");
    std::ofstream(file) << problem_text(resolution);
    world::Problem problem;
    try {
      problem = world::load_problem(file);
    } catch (const FileError& e) {
      // Refused: only below the documented floor, in one line naming the file and the field.
      EXPECT_LT(resolution, core::kMinResolutionFraction);
      const std::string what = e.what();
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
      EXPECT_EQ(what.rfind(file.string() + ": resolution: ", 0), 0u) << what;
      continue;
    }
    EXPECT_GE(resolution, core::kMinResolutionFraction) << "a resolution below the floor was loaded";
    const double cpu0 = test::thread_cpu_seconds();
    RunOutcome out;
    try {
      out = execute_run(problem, planner, {}, 7, kTimeLimit, kNodeLimit);
    } catch (const ParameterError& e) {
      ADD_FAILURE() << "a resolution the loader accepted was refused at run time: " << e.what();
      continue;
    }
    const double cpu = test::thread_cpu_seconds() - cpu0;  // load-proof: support/time_allowance.hpp
    const core::RunRecord& r = out.record;
    EXPECT_LE(cpu, kTimeLimit + kAllowance) << "status " << core::to_string(r.status);
    EXPECT_LE(r.nodes, kNodeLimit);
    switch (r.status) {
      case core::PlanStatus::kSolved:
        test::expect_valid_path(resolution >= kCheckResolution ? problem : reference, out.path,
                                resolution >= kCheckResolution ? 1 : 4);
        break;
      case core::PlanStatus::kTimeout:
      case core::PlanStatus::kNodeLimit:
        EXPECT_TRUE(out.path.empty());
        break;
      default:
        ADD_FAILURE() << "status " << core::to_string(r.status) << ": " << r.message;
    }
  }
}

TEST_F(ResolutionSweep, StraightLinePrmGivesAnErrorOrAValidPathOrStopsInTime) {
  sweep(dir_, "prm", write(kCheckResolution, "reference.yaml"));
}

TEST_F(ResolutionSweep, GridAStarPrmGivesAnErrorOrAValidPathOrStopsInTime) {
  sweep(dir_, "prm-c", write(kCheckResolution, "reference.yaml"));
}

}  // namespace
}  // namespace amp::roadmap
