#include "amp/roadmap/prm/prm.hpp"

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/path_checks.hpp"
#include "support/source_tree.hpp"

#include "amp/roadmap/path_certificate.hpp"
#include "amp/roadmap/prm/path_smoothing.hpp"
#include "roadmap/test_worlds.hpp"

namespace amp::roadmap {
namespace {

namespace fs = std::filesystem;

constexpr std::size_t kNodeLimit = 5000;
constexpr double kNoTimeLimit = 1e6;  // the node limit ends every test run, never the clock

struct Outcome {
  PlanResult result;
  std::uint64_t cd_calls = 0;
  std::uint64_t cd_query = 0;
};

Outcome run_prm(const world::Problem& p, PrmSettings settings, std::uint64_t seed,
                std::size_t node_limit = kNodeLimit, double time_limit = kNoTimeLimit) {
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  const PlanningContext ctx{*p.space, *p.environment, *checker, p.seeds};
  core::Rng rng(seed);
  const core::StopCondition stop(time_limit, node_limit);
  Prm prm(settings);
  Outcome o{prm.plan(ctx, stop, rng), counters.cd_calls(), counters.cd_calls(core::Phase::kQuery)};
  return o;
}


TEST(Prm, SolvesTheNarrowGap) {
  const world::Problem p = test::point_problem(true);
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const Outcome o = run_prm(p, {}, seed);
    ASSERT_EQ(o.result.status, core::PlanStatus::kSolved) << seed;
    amp::test::expect_valid_path(p, o.result.path, 4);
    // The path crosses the wall inside the gap.
    ASSERT_NE(o.result.roadmap, nullptr);
    EXPECT_EQ(o.result.nodes, o.result.roadmap->vertex_count());
    EXPECT_EQ(o.result.edges, o.result.roadmap->edge_count());
    EXPECT_EQ(o.result.components, o.result.roadmap->component_count());
    EXPECT_GE(o.result.nodes, 3u);
    EXPECT_EQ(o.cd_query, 0u);  // no smoothing: no query-phase checks
  }
}

TEST(Prm, SolvesTheArm) {
  const world::Problem p = test::arm_problem();
  const Outcome o = run_prm(p, {}, 5);
  ASSERT_EQ(o.result.status, core::PlanStatus::kSolved);
  amp::test::expect_valid_path(p, o.result.path, 4);
  EXPECT_GT(o.result.path.size(), 2u);  // the direct swing hits the box
}

TEST(Prm, SameSeedSameResultDifferentSeedDifferentResult) {
  const world::Problem p = test::point_problem(true);
  for (bool lazy : {false, true}) {
    PrmSettings s;
    s.lazy = lazy;
    s.smooth = true;
    const Outcome a = run_prm(p, s, 42), b = run_prm(p, s, 42), c = run_prm(p, s, 43);
    ASSERT_EQ(a.result.status, core::PlanStatus::kSolved);
    ASSERT_EQ(a.result.path.size(), b.result.path.size());
    for (std::size_t i = 0; i < a.result.path.size(); ++i) {
      for (int j = 0; j < 2; ++j) EXPECT_EQ(a.result.path[i][j], b.result.path[i][j]);  // bit for bit
    }
    EXPECT_EQ(a.cd_calls, b.cd_calls);
    EXPECT_EQ(a.result.nodes, b.result.nodes);
    EXPECT_EQ(a.result.edges, b.result.edges);
    EXPECT_TRUE(a.result.path != c.result.path || a.cd_calls != c.cd_calls);
  }
}

TEST(Prm, LazyAndSmoothedPathsAreValid) {
  const world::Problem p = test::point_problem(true);
  PrmSettings lazy;
  lazy.lazy = true;
  const Outcome l = run_prm(p, lazy, 9);
  ASSERT_EQ(l.result.status, core::PlanStatus::kSolved);
  amp::test::expect_valid_path(p, l.result.path, 4);
  EXPECT_GT(l.result.extra.at("lazy_edges_removed"), 0.0);  // the wall forces removals

  PrmSettings smooth;
  smooth.smooth = true;
  const Outcome raw = run_prm(p, {}, 9), smoothed = run_prm(p, smooth, 9);
  ASSERT_EQ(smoothed.result.status, core::PlanStatus::kSolved);
  amp::test::expect_valid_path(p, smoothed.result.path, 4);
  // Same seed: the same roadmap, then shortcuts only shorten the path (triangle inequality).
  EXPECT_EQ(raw.result.nodes, smoothed.result.nodes);
  EXPECT_LE(path_length(*p.space, smoothed.result.path), path_length(*p.space, raw.result.path) + 1e-12);
  EXPECT_GT(smoothed.cd_query, 0u);  // smoothing is charged to the query phase
}

// Lazy PRM on the bundled maze (6,570 nodes, over 60,000 edges, seed 1): every edge of a candidate
// path is checked in one pass, so candidate paths rejected are far fewer than edges removed; the path is
// certified along its whole length and joins the seeds; the run repeats; and it checks a small
// share of what plain PRM checks.
TEST(Prm, LazyPrmRemovesEveryFailedEdgeOfAPathAtOnce) {
  const world::Problem p = world::load_problem(fs::path(AMP_SOURCE_DIR) / "problems" / "maze.yaml");
  PrmSettings lazy;
  lazy.lazy = true;
  const Outcome a = run_prm(p, lazy, 1, 20000), b = run_prm(p, lazy, 1, 20000);
  ASSERT_EQ(a.result.status, core::PlanStatus::kSolved);
  amp::test::expect_valid_path(p, a.result.path);
  const PathCertificate certificate = certify_path(*p.space, *p.environment, a.result.path);
  EXPECT_TRUE(certificate.certified) << certificate.failure;
  EXPECT_EQ(a.result.path, b.result.path);
  EXPECT_EQ(a.cd_calls, b.cd_calls);
  const double removed = a.result.extra.at("lazy_edges_removed");
  const double rejected = a.result.extra.at("lazy_paths_rejected");
  // measured: 1,953 edges removed from 352 paths
  EXPECT_GT(removed, 2 * rejected) << removed << " edges removed from " << rejected << " paths";
  const Outcome plain = run_prm(p, {}, 1, 20000);
  ASSERT_EQ(plain.result.status, core::PlanStatus::kSolved);
  EXPECT_LT(a.cd_calls * 5, plain.cd_calls);  // measured: 31,888 against 758,178
}

TEST(Prm, SkipSameComponentBuildsAForest) {
  const world::Problem p = test::point_problem(true);
  PrmSettings s;
  s.skip_same_component = true;
  const Outcome o = run_prm(p, s, 4);
  ASSERT_EQ(o.result.status, core::PlanStatus::kSolved);
  amp::test::expect_valid_path(p, o.result.path, 4);
  EXPECT_EQ(o.result.edges + o.result.components, o.result.nodes);  // a forest: E = V - C
}

TEST(Prm, ConnectsEverySeedInOrder) {
  world::Problem p = test::point_problem(true);
  p.seeds = {test::state2(1, 1), test::state2(9, 9), test::state2(1, 9)};
  const Outcome o = run_prm(p, {}, 6);
  ASSERT_EQ(o.result.status, core::PlanStatus::kSolved);
  amp::test::expect_valid_path(p, o.result.path, 4);
  EXPECT_NE(std::find(o.result.path.begin(), o.result.path.end(), p.seeds[1]), o.result.path.end());
}

TEST(Prm, NodeLimitOnAnUnsolvableProblem) {
  const world::Problem p = test::point_problem(false);
  for (bool lazy : {false, true}) {
    PrmSettings s;
    s.lazy = lazy;
    const Outcome o = run_prm(p, s, 1, 300);
    EXPECT_EQ(o.result.status, core::PlanStatus::kNodeLimit);
    EXPECT_EQ(o.result.nodes, 300u);
    EXPECT_TRUE(o.result.path.empty());
    EXPECT_GE(o.result.components, 2u);
  }
}

TEST(Prm, TimeLimitOnAnUnsolvableProblem) {
  const world::Problem p = test::point_problem(false);
  const Outcome o = run_prm(p, {}, 1, static_cast<std::size_t>(-1), 0.02);
  EXPECT_EQ(o.result.status, core::PlanStatus::kTimeout);
  EXPECT_TRUE(o.result.path.empty());
}

TEST(Prm, SamplerThatNeverSucceedsStillStops) {
  world::Problem p = test::point_problem(true);
  // Everything but the two seeds' surroundings is blocked: samples fail, the node limit never
  // comes, the time limit must end the run.
  p.environment = std::make_shared<test::BoxEnvironment>(
      std::vector<test::Box>{{1.5, 0, 8.5, 10}, {0, 0, 10, 4.5}, {0, 5.5, 10, 10}}, test::RobotKind::kPoint);
  p.seeds = {test::state2(1, 5), test::state2(9, 5)};
  // No node limit: the few samples that land near the seeds must not end the run before the clock.
  // 0.1 s: long enough for a first sample on a loaded machine (0.02 s once saw none).
  const Outcome o = run_prm(p, {}, 1, static_cast<std::size_t>(-1), 0.1);
  EXPECT_EQ(o.result.status, core::PlanStatus::kTimeout);
  EXPECT_GT(o.result.extra.at("failed_samples"), 0.0);
}

TEST(Prm, RejectsBadSeedsNamingThem) {
  world::Problem p = test::point_problem(true);
  p.seeds[1] = test::state2(5, 1);  // inside the wall
  try {
    run_prm(p, {}, 1);
    FAIL() << "expected InvalidSeedError";
  } catch (const InvalidSeedError& e) {
    EXPECT_NE(std::string(e.what()).find("seed 1 (goal)"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("collision"), std::string::npos) << e.what();
  }
  p.seeds[1] = test::state2(11, 5);
  EXPECT_THROW(run_prm(p, {}, 1), InvalidSeedError);
  p.seeds = {};
  EXPECT_THROW(run_prm(p, {}, 1), InvalidSeedError);
}

TEST(PrmSettings, Validate) {
  PrmSettings s;
  s.k = 0;
  EXPECT_THROW(s.validate(), ParameterError);
  EXPECT_THROW(Prm{s}, ParameterError);
  s.k = 5;
  s.smooth_attempts = -1;
  EXPECT_THROW(s.validate(), ParameterError);
}

}  // namespace
}  // namespace amp::roadmap

namespace amp::roadmap {
namespace {

TEST(Prm, KeepsTheCallersPhaseAndChargesSmoothingToQuery) {
  const world::Problem p = test::point_problem(true);
  core::Counters counters;
  counters.set_phase(core::Phase::kTraining);  // as a learner building its training roadmap
  const auto checker = p.environment->make_checker(counters);
  const PlanningContext ctx{*p.space, *p.environment, *checker, p.seeds};
  core::Rng rng(8);
  const core::StopCondition stop(1e6, 5000);
  PrmSettings s;
  s.smooth = true;
  const PlanResult r = Prm(s).plan(ctx, stop, rng);
  ASSERT_EQ(r.status, core::PlanStatus::kSolved);
  EXPECT_EQ(counters.phase(), core::Phase::kTraining);
  EXPECT_GT(counters.cd_calls(core::Phase::kTraining), 0u);
  EXPECT_GT(counters.cd_calls(core::Phase::kQuery), 0u);
  EXPECT_EQ(counters.cd_calls(core::Phase::kPlanning), 0u);
}

}  // namespace
}  // namespace amp::roadmap
