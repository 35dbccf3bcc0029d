// The expansion step as a sampler: candidates by failure ratio, samples near them, free, in the
// domain; and Hybrid PRM / UAS with it as one more arm.
#include "amp/roadmap/samplers/expansion_sampler.hpp"

#include <cmath>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "support/path_checks.hpp"
#include "amp/core/counters.hpp"
#include "amp/core/error.hpp"
#include "amp/roadmap/run.hpp"
#include "amp/world/problem.hpp"
#include "roadmap/test_worlds.hpp"
#include "support/source_tree.hpp"

namespace amp::roadmap {
namespace {

using test::state2;

struct Fixture {
  world::Problem problem = test::point_problem(true);
  core::Counters counters;
  std::unique_ptr<world::ValidityChecker> checker = problem.environment->make_checker(counters);
  ExpansionSampler make(double d, std::shared_ptr<const SamplingDomain> domain = nullptr) {
    return ExpansionSampler(*problem.space, *checker, ExpansionSamplerSettings{d, 20}, std::move(domain));
  }
};

TEST(ExpansionSampler, WithoutCandidatesFailsAtNoCdCall) {
  Fixture f;
  ExpansionSampler s = f.make(0.2);
  s.add(state2(1, 1), 1.0);  // fully visible: weight 0, not a candidate
  EXPECT_EQ(s.candidates(), 0u);
  core::Rng rng(1);
  State out;
  EXPECT_FALSE(s.sample(rng, out));
  EXPECT_EQ(f.counters.cd_calls(), 0u);
}

TEST(ExpansionSampler, SamplesAreFreeAndNearTheirNodeChosenByFailureRatio) {
  Fixture f;
  const double d = 0.2;
  ExpansionSampler s = f.make(d);
  // Weights 1 - v: 1.0 near (2, 8) and 0.25 near (8, 8); both far from every obstacle.
  s.add(state2(2, 8), 0.0);
  s.add(state2(8, 8), 0.75);
  ASSERT_EQ(s.candidates(), 2u);
  core::Rng rng(7);
  State out;
  int near_a = 0, near_b = 0;
  const int n = 2000;
  for (int i = 0; i < n; ++i) {
    ASSERT_TRUE(s.sample(rng, out));
    EXPECT_TRUE(f.checker->is_valid(out));
    const double da = (out - state2(2, 8)).norm(), db = (out - state2(8, 8)).norm();
    // |N(0, d)| exceeds 6d with probability 2e-9.
    ASSERT_LT(std::min(da, db), 6 * d);
    (da < db ? near_a : near_b)++;
  }
  // Expected 1600 : 400 (probability 0.8); binomial sd = sqrt(2000 * 0.8 * 0.2) = 17.9, so 4.5 sd = 80.
  EXPECT_NEAR(near_a, 1600, 80);
  EXPECT_EQ(near_a + near_b, n);
}

TEST(ExpansionSampler, KeepsToItsDomainAndLearnsFromInsertions) {
  Fixture f;
  // A box over the left half: a node in the right half is no candidate, samples stay left.
  auto domain = std::make_shared<ReferencePointBoxDomain>(
      *f.problem.space, *f.problem.environment, Eigen::AlignedBox3d(Eigen::Vector3d(0, 0, -1), Eigen::Vector3d(4, 10, 1)));
  ExpansionSampler s = f.make(0.5, domain);
  Roadmap roadmap;
  const VertexId left = roadmap.add_vertex(state2(3.9, 5));
  const VertexId right = roadmap.add_vertex(state2(7, 5));
  Insertion half{left, false, 4, 2, 1};  // visibility 1/2
  s.inserted(roadmap, half);
  s.inserted(roadmap, Insertion{right, false, 4, 0, 0});
  EXPECT_EQ(s.candidates(), 1u);
  core::Rng rng(3);
  State out;
  for (int i = 0; i < 300; ++i) {
    if (!s.sample(rng, out)) continue;
    EXPECT_LE(out[0], 4.0);
    EXPECT_TRUE(f.checker->is_valid(out));
  }
  // Known nodes (a reused roadmap) are offered the same way.
  ExpansionSampler t = f.make(0.5, domain);
  t.add(VisibleNodes{std::make_shared<Roadmap>(roadmap), {0.5, 0.0}});
  EXPECT_EQ(t.candidates(), 1u);
}

TEST(ExpansionSampler, RejectsNonsenseSettings) {
  EXPECT_THROW((ExpansionSamplerSettings{0.0, 20}.validate()), ParameterError);
  EXPECT_THROW((ExpansionSamplerSettings{NAN, 20}.validate()), ParameterError);
  EXPECT_THROW((ExpansionSamplerSettings{1.0, 0}.validate()), ParameterError);
}

// As one more arm of Hybrid PRM and of every UAS region: solves with valid paths, repeats bit for bit,
// and the arm is used.
TEST(ExpansionSampler, HybridPrmAndUasSolveWithItAndRepeat) {
  const world::Problem p = world::load_problem(std::string(AMP_SOURCE_DIR) + "/problems/walls.yaml");
  for (const char* planner : {"hybrid-prm", "uas"}) {
    const core::ParamMap params{{"expansion", true}};
    const RunOutcome a = execute_run(p, planner, params, 5, 1e6, 20000);
    ASSERT_EQ(a.record.status, core::PlanStatus::kSolved) << planner;
    amp::test::expect_valid_path(p, a.path);
    EXPECT_GT(a.record.extra.at("samples_expansion"), 0.0) << planner;
    const RunOutcome b = execute_run(p, planner, params, 5, 1e6, 20000);
    EXPECT_EQ(a.path, b.path) << planner;
    EXPECT_EQ(a.record.cd_calls(), b.record.cd_calls()) << planner;
  }
}

}  // namespace
}  // namespace amp::roadmap
