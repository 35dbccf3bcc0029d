// Every planner on MotionBenchMaker's Panda problems (../shared/mbm, the first five of each scene
// family; three for uas, two for prm-g, the slow ones), seed 1, 10 s each, as
// `amp plan --urdf ... --seed 1 --time-limit 10` runs them (default node limit): a solved
// path starts at the request's start and ends at its goal exactly, and the independent check of
// world/arm/mesh_oracle.hpp (assimp meshes, KDL, FCL; no AMP code) finds every state valid along
// it, each segment interpolated in joint space with no joint moving more than 1 mrad between two
// checks. rrt-connect must solve every problem; the other planners a stated number (their counts
// are printed, with the median times). The same seed gives the same path (rrt-connect and prm).
// When a vamp-peer binary is there (build/vamp-peer/vamp_peer, or AMP_VAMP_PEER), VAMP's sphere
// model's verdict on each path is printed beside the oracle's: its spheres approximate the meshes,
// so it is compared, not asserted.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include <unistd.h>

#include "amp/core/joint_space.hpp"
#include "amp/core/parameters.hpp"
#include "amp/core/run_record.hpp"
#include "amp/roadmap/run.hpp"
#include "amp/world/arm_problem.hpp"
#include "support/sanitizer_build.hpp"
#include "world/arm/mesh_oracle.hpp"
#include "support/source_tree.hpp"

namespace amp {
namespace {

namespace fs = std::filesystem;

constexpr std::uint64_t kSeed = 1;
constexpr double kTimeLimitS = 10.0;
// The oracle's step: no joint moves more than this (rad) between two checked states.
constexpr double kOracleStep = 0.001;
const std::vector<std::string> kFamilies = {"box", "table_pick", "bookshelf_small"};

struct PlannerCase {
  std::string label;  // the test's name
  std::string planner;
  core::ParamMap params;
  int problems_per_family;  // the first ones: 5, or fewer for a slow planner
  int min_solved;           // of the 3 x problems_per_family runs; all of them: each run must solve
  bool check_determinism;
};

std::ostream& operator<<(std::ostream& out, const PlannerCase& c) { return out << c.label; }

// What one planner did on one family.
struct FamilyFigures {
  int solved = 0, runs = 0;
  std::vector<double> times;  // wall time of every run, solved or not
  long long oracle_states = 0, oracle_invalid = 0;
  int vamp_checked = 0, vamp_accepted = 0;
};

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The vamp-peer binary, if one is there (it is optional and never built here).
std::optional<fs::path> vamp_peer() {
  if (const char* env = std::getenv("AMP_VAMP_PEER"); env != nullptr && *env != '\0') {
    if (fs::is_regular_file(env)) return fs::path(env);
    return std::nullopt;
  }
  const fs::path built = fs::path(AMP_BINARY_DIR) / "vamp-peer" / "vamp_peer";
  if (fs::is_regular_file(built)) return built;
  return std::nullopt;
}

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (const char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// vamp_peer --check-path's summary line ("path: 4/4 states valid, 3/3 segments valid, ..."), and
// whether it accepts every state and segment. Empty when the peer did not print one.
struct VampVerdict {
  std::string line;
  bool accepted = false;
};

VampVerdict vamp_check(const fs::path& peer, const fs::path& scene, const fs::path& request, const fs::path& path_file) {
  const std::string command = shell_quote(peer.string()) + " --robot panda --scene " + shell_quote(scene.string()) + " --request " +
                              shell_quote(request.string()) + " --runs 0 --check-path " + shell_quote(path_file.string()) + " 2>&1";
  VampVerdict v;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return v;
  std::string output;
  char buffer[512];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) output += buffer;
  pclose(pipe);
  std::istringstream lines(output);
  std::string start_goal;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("path:", 0) == 0) v.line = line;
    if (line.find("start valid") != std::string::npos) start_goal = line.substr(line.find("start valid"));
  }
  if (v.line.empty()) {
    v.line = "no verdict: " + output.substr(0, 200);
    return v;
  }
  int states_ok = 0, segments_ok = 0;
  std::size_t states = 0, segments = 0;
  if (std::sscanf(v.line.c_str(), "path: %d/%zu states valid, %d/%zu segments valid", &states_ok, &states, &segments_ok, &segments) == 4) {
    v.accepted = states_ok == static_cast<int>(states) && segments_ok == static_cast<int>(segments);
  }
  if (!start_goal.empty()) v.line += " (" + start_goal + ")";
  return v;
}

// The path as `amp plan --out` writes an arm's: one state per line, the group's joint values.
void write_path(const fs::path& file, const std::vector<State>& path) {
  std::ofstream out(file);
  out << std::setprecision(17);
  for (const State& s : path) {
    for (int k = 0; k < s.size(); ++k) out << (k > 0 ? " " : "") << s[k];
    out << '\n';
  }
}

// The oracle along the path: each segment a -> b in joint space (continuous joints the short way
// round, as AMP interpolates them), n equal steps with no joint moving more than kOracleStep.
// Returns the states checked; `invalid` counts the invalid ones, the first few reported.
long long oracle_path_check(const test::OracleCheck& check, const test::OracleGroup& group, const core::JointSpace& space,
                            const std::vector<State>& path, const std::string& what, long long& invalid) {
  const int dim = space.dimension();
  std::vector<double> values;
  long long states = 0;
  State delta(dim), q(dim);
  for (std::size_t i = 0; i < path.size(); ++i) {
    const State& a = path[i];
    long long steps = 0;  // 0: the first state alone
    if (i > 0) {
      const State& from = path[i - 1];
      for (int k = 0; k < dim; ++k) {
        const bool wraps = space.joints()[static_cast<std::size_t>(k)].kind == core::JointKind::kContinuous;
        delta[k] = wraps ? core::angle_difference(from[k], a[k]) : a[k] - from[k];
      }
      steps = std::max<long long>(1, static_cast<long long>(std::ceil(delta.cwiseAbs().maxCoeff() / kOracleStep)));
    }
    for (long long j = (i == 0 ? 0 : 1); j <= steps; ++j) {
      if (j == steps) {
        q = a;  // the path's own state, exactly
      } else {
        q = path[i - 1] + delta * (static_cast<double>(j) / static_cast<double>(steps));
      }
      group.values(q, values);
      const test::Verdict verdict = check.check(values);
      ++states;
      if (!verdict.valid && ++invalid <= 5) {
        ADD_FAILURE() << what << ": segment " << i << " step " << j << "/" << steps << " (" << q.transpose()
                      << ") is invalid by the independent check: " << verdict.contact;
      }
    }
  }
  return states;
}

class ArmPlanners : public ::testing::TestWithParam<PlannerCase> {
 protected:
  static void SetUpTestSuite() {
    if (test::kSanitizerBuild) return;  // every case skips: nothing to load
    const fs::path dir = test::mbm_panda_dir();
    if (!fs::is_regular_file(dir / "panda.urdf") || !fs::is_directory(dir / "problems")) return;
    robot_ = std::make_unique<world::ArmDescription>(world::load_arm_description(dir / "panda.urdf", dir / "panda.srdf"));
    oracle_ = std::make_unique<test::OracleRobot>(dir / "panda.urdf", dir / "panda.srdf");
  }
  static void TearDownTestSuite() {
    robot_.reset();
    oracle_.reset();
  }
  static std::unique_ptr<world::ArmDescription> robot_;
  static std::unique_ptr<test::OracleRobot> oracle_;
};
std::unique_ptr<world::ArmDescription> ArmPlanners::robot_;
std::unique_ptr<test::OracleRobot> ArmPlanners::oracle_;

TEST_P(ArmPlanners, SolvedPathsJoinTheRequestAndPassTheIndependentCheck) {
  if (test::kSanitizerBuild) GTEST_SKIP() << "planner runs of up to 10 s each: not under the sanitizers";
  if (!robot_) GTEST_SKIP() << test::mbm_panda_dir() << " is absent (the shared MotionBenchMaker data, ../shared/mbm beside the source tree)";
  const PlannerCase& c = GetParam();
  const std::optional<fs::path> peer = vamp_peer();
  // The paths as files for vamp-peer, removed however the test ends.
  struct TempDir {
    fs::path path = fs::temp_directory_path() / ("amp-arm-planners-" + std::to_string(::getpid()));
    TempDir() { fs::create_directories(path); }
    ~TempDir() {
      std::error_code ignored;
      fs::remove_all(path, ignored);
    }
  } tmp;

  std::map<std::string, FamilyFigures> figures;
  for (const std::string& family : kFamilies) {
    FamilyFigures& f = figures[family];
    for (int i = 1; i <= c.problems_per_family; ++i) {
      const fs::path dir = test::mbm_panda_dir() / "problems" / family;
      const fs::path scene = dir / ("scene" + test::scene_number(i) + ".yaml");
      const fs::path request = dir / ("request" + test::scene_number(i) + ".yaml");
      const std::string what = c.label + " " + family + "/" + test::scene_number(i);
      const world::Problem problem = world::load_arm_problem(*robot_, scene, request);
      const auto& space = dynamic_cast<const core::JointSpace&>(*problem.space);

      const roadmap::RunOutcome run = roadmap::execute_run(problem, c.planner, c.params, kSeed, kTimeLimitS, std::nullopt);
      ++f.runs;
      f.times.push_back(run.record.wall_time_s);
      const bool solved = run.record.status == core::PlanStatus::kSolved;
      std::cout << "[ run      ] " << what << ": " << core::to_string(run.record.status) << " in " << run.record.wall_time_s << " s, "
                << run.record.nodes << " nodes, " << run.path.size() << " path states";
      if (solved) std::cout << ", AMP's clearance " << run.record.path_clearance * 1000.0 << " mm";
      if (!solved) {
        std::cout << std::endl;
        if (c.min_solved == 3 * c.problems_per_family) ADD_FAILURE() << what << ": " << core::to_string(run.record.status) << " " << run.record.message;
        continue;
      }
      ++f.solved;

      // Ends: exactly the problem's start and goal, and the request file's values by joint name.
      EXPECT_GE(run.path.size(), 2u) << what;
      EXPECT_TRUE(run.path.front() == problem.start()) << what << ": starts at " << run.path.front().transpose();
      EXPECT_TRUE(run.path.back() == problem.goal()) << what << ": ends at " << run.path.back().transpose();
      const std::map<std::string, double> start = test::request_start(request), goal = test::request_goal(request);
      for (int k = 0; k < space.dimension(); ++k) {
        const std::string& name = space.joints()[static_cast<std::size_t>(k)].name;
        EXPECT_EQ(run.path.front()[k], start.at(name)) << what << ": " << name << " at the start";
        EXPECT_EQ(run.path.back()[k], goal.at(name)) << what << ": " << name << " at the goal";
      }

      // The independent check along the whole path.
      const test::OracleScene oracle_scene(scene);
      const test::OracleCheck check(*oracle_, oracle_scene);
      std::vector<std::string> names;
      for (const core::Joint& j : space.joints()) names.push_back(j.name);
      const test::OracleGroup group(*oracle_, names, start);
      long long invalid = 0;
      const long long states = oracle_path_check(check, group, space, run.path, what, invalid);
      f.oracle_states += states;
      f.oracle_invalid += invalid;
      std::cout << "; oracle: " << states - invalid << "/" << states << " states valid";

      const fs::path path_file = tmp.path / (c.label + "-" + family + "-" + test::scene_number(i) + ".path");
      write_path(path_file, run.path);
      if (peer) {
        const VampVerdict v = vamp_check(*peer, scene, request, path_file);
        ++f.vamp_checked;
        f.vamp_accepted += v.accepted ? 1 : 0;
        std::cout << "; VAMP " << (v.accepted ? "accepts" : "rejects") << ": " << v.line;
      }
      std::cout << '\n';

      if (c.check_determinism) {
        const roadmap::RunOutcome again = roadmap::execute_run(problem, c.planner, c.params, kSeed, kTimeLimitS, std::nullopt);
        ASSERT_EQ(again.record.status, run.record.status) << what << ": the same seed, another status";
        ASSERT_EQ(again.path.size(), run.path.size()) << what << ": the same seed, another path";
        for (std::size_t s = 0; s < run.path.size(); ++s) EXPECT_TRUE(again.path[s] == run.path[s]) << what << ": state " << s;
        EXPECT_EQ(again.record.cd_calls(), run.record.cd_calls()) << what;
        EXPECT_EQ(again.record.nodes, run.record.nodes) << what;
      }
    }
  }

  int solved = 0, runs = 0;
  for (const std::string& family : kFamilies) {
    const FamilyFigures& f = figures[family];
    solved += f.solved;
    runs += f.runs;
    std::cout << "[ figures  ] " << c.label << " " << family << ": solved " << f.solved << "/" << f.runs << ", median time "
              << median(f.times) << " s (unsolved runs at their own time); oracle: " << f.oracle_states - f.oracle_invalid << "/"
              << f.oracle_states << " states valid";
    if (peer) std::cout << "; VAMP accepts " << f.vamp_accepted << "/" << f.vamp_checked << " paths";
    std::cout << '\n';
  }
  if (!peer) std::cout << "[ figures  ] no vamp-peer binary (build/vamp-peer/vamp_peer or AMP_VAMP_PEER): VAMP's verdicts not taken\n";
  std::cout << "[ figures  ] " << c.label << ": solved " << solved << "/" << runs << " (at least " << c.min_solved << " required)\n";
  EXPECT_GE(solved, c.min_solved) << c.label << " solved " << solved << " of " << runs;
}

// What each planner must solve, from runs on 2 shared cores (load 3-4.5; wall times, so a busy
// machine solves less; the counts are printed). rrt-connect (MoveIt's default) solves every problem
// in 1.5 s at most; so do prm-c (1.2 s) and prm-l (3.4-6.3 s on bookshelf_small 5, hence 14).
// prm, Lazy PRM and Hybrid PRM: 12 of 15; all three fail on table_pick 3, bookshelf_small 2 and 5
// (prm and hybrid-prm time out with 4 components among 2,000-2,900 nodes, Lazy PRM reaches the
// 20,000-node default limit in 2.5-3.2 s). uas, on the first 3 of each family: 6 of 9 (it times out
// on table_pick 3, bookshelf_small 2 and 3; on 5 of 15 it solves 11). prm-g takes 3-10 s per
// problem, near the limit on box 1-2 and table_pick 2: the first 2 of each family, at least 4 of 6
// (6 of 6 at load 3, 5 of 6 at load 4.5).
INSTANTIATE_TEST_SUITE_P(MotionBenchMaker, ArmPlanners,
                         ::testing::Values(PlannerCase{"rrt_connect", "rrt-connect", {}, 5, 15, true},
                                           PlannerCase{"prm", "prm", {}, 5, 12, true},
                                           PlannerCase{"prm_lazy", "prm", {{"lazy", true}}, 5, 12, false},
                                           PlannerCase{"hybrid_prm", "hybrid-prm", {}, 5, 12, false},
                                           PlannerCase{"uas", "uas", {}, 3, 6, false},
                                           PlannerCase{"prm_c", "prm-c", {}, 5, 15, false},
                                           PlannerCase{"prm_g", "prm-g", {}, 2, 4, false},
                                           PlannerCase{"prm_l", "prm-l", {}, 5, 14, false}),
                         [](const ::testing::TestParamInfo<PlannerCase>& info) { return info.param.label; });

}  // namespace
}  // namespace amp
