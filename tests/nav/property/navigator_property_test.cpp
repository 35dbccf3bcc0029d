// Property tests of the navigation methods (issue 17) on random worlds drawn from fixed seeds:
// pgcs on polygon worlds and MovingAI maps, policy-search and dwa on maps, static, random and sins
// in empty boxes (they draw their own clutter worlds). For every run:
//  - it ends within its time limit + 5 % + 50 ms;
//  - the robot never overlaps an obstacle or leaves the world at a recorded position, and never
//    passes through one between two positions (the test's own exact geometry, from the file);
//  - a goal reported reached is where the robot stands (pgcs: each solved query's target; policy
//    and dwa: within goal_tolerance; sins: the last step passes within goal_tolerance).
// pgcs and the sins systems record no per-query or per-world trace, so their runs are repeated
// here through the same public pieces (PgcsSession, run_world) and the copy is first checked to
// give the method's own record, then its traces are checked.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/core/stop_condition.hpp"
#include "amp/nav/navigator_catalog.hpp"
#include "amp/nav/pgcs/pgcs_session.hpp"
#include "amp/nav/sins/parameter_policy.hpp"
#include "amp/nav/sins/sins_navigator.hpp"
#include "amp/nav/sins/sins_run.hpp"
#include "amp/world/problem.hpp"
#include "support/exact_geometry.hpp"
#include "support/planner_runs.hpp"
#include "support/random_problems.hpp"
#include "support/sanitizer_build.hpp"
#include "support/time_allowance.hpp"

namespace amp::nav {
namespace {

namespace fs = std::filesystem;
using test::Vec2;

constexpr std::uint64_t kMasterSeed = 0x17'0002'0004ULL;
constexpr double kReplicaTimeLimit = 600.0;  // the copies of a run must not be cut short

// The gap of the disc swept along a -> b to everything in the world (< 0: overlap).
double swept_gap(const test::PlanarModel& m, const Vec2& a, const Vec2& b, double r) {
  double g = std::min(test::inner_slack(m.bounds, a, r), test::inner_slack(m.bounds, b, r));
  const test::Box2 sb{a.cwiseMin(b), a.cwiseMax(b)};
  const auto polygon_gap = [&](const test::Poly& p) {
    if (test::point_in_polygon(a, p)) return -r;
    double d = test::kInf;
    for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) d = std::min(d, test::segment_segment_distance(a, b, p[j], p[i]));
    return d - r;
  };
  for (std::size_t k = 0; k < m.polygons.size(); ++k) {
    if (test::box_box_distance(sb, m.polygon_boxes[k]) - r < g) g = std::min(g, polygon_gap(m.polygons[k]));
  }
  for (const test::Box2& cell : m.cells) {
    if (test::box_box_distance(sb, cell) - r < g) g = std::min(g, polygon_gap(test::box_polygon(cell)));
  }
  for (const test::Disc& c : m.circles) g = std::min(g, test::point_segment_distance(c.c, a, b) - c.r - r);
  return g;
}

// "" when the disc of radius r is free (touching allowed) at every position and cannot have passed
// through anything between two: each step is at most `max_step` long, and the driven curve of a
// step (`curved`: a unicycle's arc; else a straight move) lies within b of its chord, b the half
// minor axis of the ellipse of curves no longer than max_step, so the chord's sweep may come no
// nearer than r - b.
std::string check_trace(const test::PlanarModel& m, const std::vector<Vec2>& trace, double r, double max_step, bool curved) {
  const double tol = 1e-9 * (m.bounds.hi - m.bounds.lo).maxCoeff();
  test::Placed placed;
  test::PlanarModel disc = m;
  disc.robot = test::disc_robot(r);
  for (std::size_t i = 0; i < trace.size(); ++i) {
    const double g = test::clearance(disc, State(trace[i]), placed);
    if (g < -tol) return "position " + std::to_string(i) + " (" + test::state_yaml(trace[i]) + "): overlap " + test::num(-g);
    if (i == 0 || !std::isfinite(max_step)) continue;  // no max_step: positions only
    const double chord = (trace[i] - trace[i - 1]).norm();
    if (chord > max_step * (1 + 1e-9) + tol) return "step " + std::to_string(i) + " is " + test::num(chord) + " long, above " + test::num(max_step);
    const double b = curved ? std::sqrt(std::max(0.0, 0.25 * (max_step * max_step - chord * chord))) : 0.0;
    const double s = swept_gap(m, trace[i - 1], trace[i], r);
    if (s < -b - tol) return "step " + std::to_string(i) + " passes through an obstacle: swept overlap " + test::num(-s);
  }
  return "";
}

struct NavCase : test::DrawnCase<test::PlanarModel> {
  std::string method;

  std::string describe() const {
    std::string s = "case " + std::to_string(index) + ": " + method + " on " + file.string() + " --seed " + std::to_string(seed);
    for (const auto& [k, v] : params) s += " --param " + k + "=" + v.to_string();
    return s + "\n" + model.yaml;
  }
};

// A problem for `method`: maps for policy-search and dwa (and half of pgcs's), polygon worlds for
// the rest of pgcs, an empty box at the origin for the sins systems.
NavCase make_case(const std::string& method, int index, const fs::path& dir) {
  NavCase c;
  c.index = index;
  c.method = method;
  std::uint64_t stream = 0;  // one stream of cases per method
  for (const char ch : method) stream = 131 * stream + static_cast<unsigned char>(ch);
  core::Rng rng(core::derive_seed(core::derive_seed(kMasterSeed, stream), static_cast<std::uint64_t>(index)));
  test::PlanarOptions o;
  o.disc_only = true;
  o.plan_settings = false;
  const bool sins = method == "static" || method == "random" || method == "sins" || method == "sins-plus";
  o.map = method == "policy-search" || method == "dwa" || (method == "pgcs" && index % 2 == 1);
  if (o.map) {  // metre-sized rooms, as the unicycle's default limits expect
    o.min_cells = 20, o.max_cells = 40, o.min_cell = 0.05, o.max_cell = 0.1;
    o.min_disc_cells = 1.0, o.max_disc_cells = 2.5, o.max_density = 0.02, o.max_walls = 2;
  }
  if (sins) {
    const double w = rng.uniform(8, 20), h = rng.uniform(8, 20), r = rng.uniform(0.15, 0.4);
    c.model.bounds = {{0, 0}, {w, h}};
    c.model.robot = test::disc_robot(r);
    c.model.start = State(Vec2(w / 2, h / 2));
    c.model.goal = State(Vec2(w / 2, h / 2 + 1));
    c.model.yaml = "bounds: {min: [0, 0], max: " + test::point_yaml({w, h}) + "}\nrobot: {type: disc, radius: " + test::num(r) +
                   "}\nstart: " + test::state_yaml(c.model.start) + "\ngoal: " + test::state_yaml(c.model.goal) + "\n";
    c.params = {{"worlds", static_cast<double>(1 + rng.uniform_index(3))},
                {"step_limit", static_cast<double>(100 + rng.uniform_index(300))},
                {"clutter", rng.uniform(0.05, 0.3)},
                {"goal_tolerance", rng.uniform(0.2, 1.0)},
                {"max_speed", rng.uniform(0.3, 1.0)}};
  } else {
    c.model = test::random_planar(rng.next_u64(), o);
  }
  if (method == "pgcs") {
    c.params = {{"steps", static_cast<double>(500 + rng.uniform_index(2500))},
                {"queries", static_cast<double>(1 + rng.uniform_index(4))},
                {"max_replans", static_cast<double>(rng.uniform_index(20))},
                {"speed", rng.uniform(0.1, 1.0)},
                {"exploration", rng.uniform01() < 0.5 ? "random-walk" : "novelty"},
                {"retreat", rng.uniform01() < 0.7},
                {"detour", rng.uniform(0, 6)},
                {"curve_points", 2.0},  // the curves' coverage samples cost more than the walk
                {"reference_cell", (c.model.bounds.hi - c.model.bounds.lo).maxCoeff() / 64}};
  }
  if (method == "policy-search" || method == "dwa") {
    const double r = c.model.robot.radius;
    c.params = {{"v_max", rng.uniform(0.2, 0.5)},
                {"time_step", rng.uniform(0.05, 0.2)},
                {"max_time", rng.uniform(10, 40)},
                {"goal_tolerance", rng.uniform(0.05, 0.2)},
                {"footprint_length", rng.uniform01() < 0.3 ? 2 * r * rng.uniform(1.0, 1.6) : 0.0}};
    if (method == "dwa") {
      c.params.emplace("v_samples", static_cast<double>(3 + rng.uniform_index(8)));
      c.params.emplace("omega_samples", static_cast<double>(3 + rng.uniform_index(8)));
      c.params.emplace("sim_time", rng.uniform(0.5, 2.0));
    } else {
      c.params.emplace("max_insertions", static_cast<double>(rng.uniform_index(10)));
    }
  }
  const std::string name = method + "-" + std::to_string(index);
  fs::create_directories(dir / name);
  c.file = dir / name / "problem.yaml";
  std::ofstream(c.file) << "name: " << name << "\n" << c.model.yaml;
  if (o.map) std::ofstream(dir / name / "map.map") << c.model.map_text;
  c.problem = world::load_problem(c.file);
  c.seed = rng.next_u64() >> 16;
  c.time_limit_s = rng.uniform(0.5, 2.0);
  if (index % 5 == 4) {  // work for minutes, so that the time limit ends the run
    c.time_limit_s = rng.uniform(0.05, 0.2);
    const auto set = [&c](const char* name, double v) { c.params.insert_or_assign(name, v); };
    if (method == "pgcs") set("steps", 1e7);
    if (sins) set("worlds", 1e5);
    if (!sins && method != "pgcs") set("max_time", 1e5), set("goal_tolerance", 1e-5);  // hardly ever arrives
    if (method == "dwa") set("v_samples", 60), set("omega_samples", 60);
    if (method == "policy-search") set("max_insertions", 1000);
  }
  return c;
}

// The method's run, timed. A ParameterError is the method refusing the problem (no passage wide
// enough for the footprint, a rectangle that cannot turn at the start, ...): false.
bool run_within_limit(const NavCase& c, NavigationOutcome& out) {
  const double cpu0 = test::thread_cpu_seconds();
  try {
    out = execute_navigation(c.problem, c.method, c.params, c.seed, c.time_limit_s);
  } catch (const ParameterError&) {
    return false;
  }
  const double cpu = test::thread_cpu_seconds() - cpu0;  // load-proof: support/time_allowance.hpp
  EXPECT_LE(cpu, c.time_limit_s + test::time_allowance(c.time_limit_s)) << c.describe();
  EXPECT_NE(out.record.status, core::PlanStatus::kError) << out.record.message << "\n" << c.describe();
  return true;
}

core::Params params_of(const NavCase& c) {
  return core::Params(c.method, builtin_navigators().info(c.method).params, c.params);
}

class NavProperties : public ::testing::Test {
 protected:
  test::TempDir dir_{"nav-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name())};
};

TEST_F(NavProperties, PgcsSolvedQueriesEndAtTheirTargetsAndNoTracePassesThroughAnObstacle) {
  int queries = 0, solved = 0;
  for (int i = 0; i < test::case_share(40); ++i) {
    const NavCase c = make_case("pgcs", i, dir_.path());
    NavigationOutcome out;
    ASSERT_TRUE(run_within_limit(c, out));
    const double r = c.model.robot.radius;
    EXPECT_EQ(check_trace(c.model, out.trace, r, test::kInf, false), "") << "exploration\n" << c.describe();
    if (out.record.status == core::PlanStatus::kTimeout) continue;  // cut short: the copy would differ
    const core::Params p = params_of(c);
    const PgcsRunSettings run = PgcsRunSettings::schema().read(p);
    PgcsSession session(make_nav_task(c.problem), run, learn::PgcsSettings::schema().read(p), core::Rng(c.seed).next_u64());
    const core::StopCondition stop(kReplicaTimeLimit, static_cast<std::size_t>(-1));
    ASSERT_TRUE(session.explore(run.steps, &stop));
    double length = 0.0;
    int solved_here = 0;
    for (const auto& [from, to] : session.draw_queries(run.queries)) {
      const QueryRecord q = session.query(from, to, &stop);
      ++queries;
      length += q.length;
      solved_here += q.solved ? 1 : 0;
      EXPECT_EQ(check_trace(c.model, q.trace, r, run.speed * r, false), "") << "query " << queries << "\n" << c.describe();
      ASSERT_FALSE(q.trace.empty());
      EXPECT_EQ(q.trace.front(), from);
      if (q.solved) {
        EXPECT_LE((q.trace.back() - to).norm(), 1e-7 * (c.model.bounds.hi - c.model.bounds.lo).maxCoeff())
            << "a query reported solved short of its target\n" << c.describe();
      }
    }
    solved += solved_here;
    EXPECT_EQ(out.record.extra.at("queries_solved"), solved_here) << "the copy differs from the run\n" << c.describe();
    EXPECT_EQ(out.record.path_length, length) << "the copy differs from the run\n" << c.describe();
    EXPECT_EQ(out.record.status == core::PlanStatus::kSolved, solved_here == static_cast<int>(run.queries)) << c.describe();
  }
  std::cout << "pgcs: " << solved << " of " << queries << " queries solved\n";
  EXPECT_GT(solved, 0);
}

// policy-search and dwa: the run's own trace, a unicycle's arcs.
void expect_driven_runs(const std::string& method, const fs::path& dir) {
  int ran = 0, arrived = 0;
  const int drawn = test::case_share(40);
  for (int i = 0; i < drawn; ++i) {
    const NavCase c = make_case(method, i, dir);
    NavigationOutcome out;
    if (!run_within_limit(c, out)) continue;
    ++ran;
    const core::Params p = params_of(c);
    const double step = p.real("v_max") * p.real("time_step");
    EXPECT_EQ(check_trace(c.model, out.trace, c.model.robot.radius, step, true), "") << c.describe();
    if (out.record.status != core::PlanStatus::kSolved) continue;
    ++arrived;
    ASSERT_FALSE(out.trace.empty());
    const Vec2 goal(c.model.goal[0], c.model.goal[1]);
    EXPECT_LE((out.trace.back() - goal).norm(), p.real("goal_tolerance"))
        << "reported arrived " << (out.trace.back() - goal).norm() << " from the goal\n" << c.describe();
  }
  std::cout << method << ": " << arrived << " of " << ran << " runs arrived (" << drawn << " drawn)\n";
  EXPECT_GE(ran, drawn / 2);
  EXPECT_GT(arrived, 0);
}

TEST_F(NavProperties, PolicySearchArrivesOnlyAtTheGoalAndNeverPassesThroughAnObstacle) {
  expect_driven_runs("policy-search", dir_.path());
}

TEST_F(NavProperties, DwaArrivesOnlyAtTheGoalAndNeverPassesThroughAnObstacle) { expect_driven_runs("dwa", dir_.path()); }

// static, random, sins and sins-plus: each world of the sequence run again with its trace, as run_sequence
// runs it (SinsNavigator: the sequence's seed is the run's first draw).
TEST_F(NavProperties, SinsSystemsSolveOnlyWorldsTheyCrossAndNeverPassThroughACircle) {
  int worlds = 0, solved = 0;
  for (const std::string method : {"static", "random", "sins", "sins-plus"}) {
    for (int i = 0; i < 12; ++i) {
      const NavCase c = make_case(method, i, dir_.path());
      NavigationOutcome out;
      ASSERT_TRUE(run_within_limit(c, out));
      if (out.record.status == core::PlanStatus::kTimeout) continue;
      const core::Params p = params_of(c);
      const SinsSettings settings = SinsNavigator::arena_settings(SinsSettings::schema().read(p), make_nav_task(c.problem));
      const bool initial = method != "random", cases = method == "sins", plus = method == "sins-plus";
      const auto policy = make_parameter_policy(
          method == "sins" ? "adaptive" : method, cases ? learn::CaseSettings::schema().read(p) : learn::CaseSettings{},
          initial ? SchemaParameters::schema().read(p) : SchemaParameters::middle(), settings.stall_exploration,
          plus ? learn::SplittingCaseSettings::schema().read(p) : learn::SplittingCaseSettings{});
      const std::uint64_t seed = core::Rng(c.seed).next_u64();
      ClutterWorldSequence sequence(seed, settings.world);
      core::Rng rng(core::derive_seed(seed, kRobotStream));
      double distance = 0.0;
      int solved_here = 0;
      for (int w = 0; w < settings.worlds; ++w) {
        const ClutterWorld world = sequence.next();
        WorldTrace trace;
        const WorldOutcome o = run_world(world, w, *policy, settings, rng, nullptr, &trace);
        ++worlds;
        distance += o.distance;
        solved_here += o.solved ? 1 : 0;
        test::PlanarModel m;
        m.bounds = {{0, 0}, {settings.world.width, settings.world.height}};
        for (const world::Circle& circle : world.circles) m.circles.push_back({circle.center, circle.radius});
        m.yaml = "world " + std::to_string(w) + "\n";
        EXPECT_EQ(check_trace(m, trace.positions, settings.world.robot_radius, settings.motor.max_speed, false), "")
            << "world " << w << "\n" << c.describe();
        const auto& x = trace.positions;
        if (o.solved) {
          ASSERT_GE(x.size(), 1u);
          const Vec2 from = x.size() > 1 ? x[x.size() - 2] : x.back();
          EXPECT_LE(test::point_segment_distance(world.goal, from, x.back()), settings.goal_tolerance)
              << "world " << w << " reported solved short of its goal\n" << c.describe();
        }
      }
      solved += solved_here;
      EXPECT_EQ(out.record.extra.at("solved_fraction"), static_cast<double>(solved_here) / settings.worlds)
          << "the copy differs from the run\n" << c.describe();
      EXPECT_NEAR(out.record.path_length, distance, 1e-9 * (1 + distance)) << "the copy differs from the run\n" << c.describe();
    }
  }
  std::cout << "sins systems: " << solved << " of " << worlds << " worlds solved\n";
  EXPECT_GT(solved, 0);
}

}  // namespace
}  // namespace amp::nav
