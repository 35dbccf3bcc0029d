// uas/training_roadmap.cpp: UAS's training roadmap, its sampler proportions and node visibilities.
#include "amp/roadmap/uas/training_roadmap.hpp"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/world/problem.hpp"
#include "roadmap/test_worlds.hpp"
#include "support/bundled_problems.hpp"

namespace amp::roadmap {
namespace {

constexpr double kNoTimeLimit = 1e6;

const world::Problem& bundled(const std::string& name) { return amp::test::bundled_problem(name + ".yaml"); }

TEST(TrainingRoadmap, HasFixedSamplerProportionsVisibilitiesAndCountsItsCdCalls) {
  const world::Problem& p = bundled("maze");
  core::Counters counters;
  counters.set_phase(core::Phase::kTraining);
  const auto checker = p.environment->make_checker(counters);
  const PlanningContext ctx{*p.space, *p.environment, *checker, p.seeds};
  core::Rng rng(3);
  const core::StopCondition stop(kNoTimeLimit, 1000000);
  const TrainingSet t = build_training_roadmap(ctx, TrainingSettings{}, stop, rng);
  ASSERT_EQ(t.size(), 200u);
  EXPECT_EQ(t.roadmap->vertex_count(), 200u);
  EXPECT_EQ(std::count(t.sampler.begin(), t.sampler.end(), 0), 67);  // uniform, Gaussian, OBPRM in turn
  EXPECT_EQ(std::count(t.sampler.begin(), t.sampler.end(), 1), 67);
  EXPECT_EQ(std::count(t.sampler.begin(), t.sampler.end(), 2), 66);
  core::Counters check;
  const auto fresh = p.environment->make_checker(check);
  for (std::size_t i = 0; i < t.size(); ++i) {
    EXPECT_TRUE(fresh->is_valid(t.roadmap->state(i)));
    EXPECT_GE(t.visibility[i], 0.0);
    EXPECT_LE(t.visibility[i], 1.0);
    EXPECT_TRUE(t.positions[i].isApprox(p.environment->reference_point(t.roadmap->state(i))));
  }
  EXPECT_EQ(t.visibility[0], 1.0);  // no neighbour yet: open by convention
  // The maze has narrow tunnels: some training nodes see few of their neighbours.
  EXPECT_LT(*std::min_element(t.visibility.begin(), t.visibility.end()), 0.5);
  const Eigen::MatrixXd f = t.features();
  ASSERT_EQ(f.cols(), 3);  // planar: visibility, X, Y
  EXPECT_EQ(f(5, 0), t.visibility[5]);
  EXPECT_EQ(f(5, 2), t.positions[5].y());
  EXPECT_GT(counters.cd_calls(core::Phase::kTraining), 0u);
  EXPECT_EQ(counters.cd_calls(core::Phase::kPlanning), 0u);
}

// training_visibility=all: the same roadmap, and each node's visibility = its edges / every attempt it
// took part in, recounted here by brute force (node j tried its k nearest among nodes 0..j-1).
TEST(TrainingRoadmap, VisibilityOverAllAttemptsMatchesABruteForceRecount) {
  const world::Problem& p = bundled("maze");
  const core::StopCondition stop(kNoTimeLimit, 1000000);
  auto build = [&](TrainingVisibility visibility) {
    core::Counters counters;
    const auto checker = p.environment->make_checker(counters);
    const PlanningContext ctx{*p.space, *p.environment, *checker, p.seeds};
    core::Rng rng(11);
    TrainingSettings settings;
    settings.visibility = visibility;
    return build_training_roadmap(ctx, settings, stop, rng);
  };
  const TrainingSet own = build(TrainingVisibility::kInsertion);
  const TrainingSet all = build(TrainingVisibility::kAllAttempts);
  ASSERT_EQ(own.size(), all.size());
  ASSERT_EQ(own.roadmap->edge_count(), all.roadmap->edge_count());
  const std::size_t n = all.size();
  const std::size_t k = static_cast<std::size_t>(TrainingSettings{}.k);
  std::vector<std::size_t> tried(n, 0);
  for (std::size_t j = 1; j < n; ++j) {
    std::vector<std::pair<double, std::size_t>> d;
    for (std::size_t i = 0; i < j; ++i) d.emplace_back(p.space->distance(all.roadmap->state(j), all.roadmap->state(i)), i);
    const std::size_t m = std::min(k, j);
    std::partial_sort(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(m), d.end());
    tried[j] += m;
    for (std::size_t t = 0; t < m; ++t) ++tried[d[t].second];
  }
  int differ = 0;
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_TRUE(all.roadmap->state(i) == own.roadmap->state(i));
    const double expected = tried[i] == 0 ? 1.0 : static_cast<double>(all.roadmap->edges(i).size()) / static_cast<double>(tried[i]);
    EXPECT_NEAR(all.visibility[i], expected, 1e-12) << "node " << i;
    differ += all.visibility[i] != own.visibility[i];
  }
  EXPECT_GT(differ, 0);  // the option changes the feature
}

TEST(TrainingRoadmap, WithNoFreeSpaceFailsWithAClearMessage) {
  // The whole square is one obstacle; no seeds (the training step does not need them).
  const std::vector<State> none;
  world::Problem p;
  p.space = std::make_shared<core::JointSpace>(core::make_rn_space({0, 0}, {10, 10}));
  p.environment = std::make_shared<test::BoxEnvironment>(std::vector<test::Box>{{-1, -1, 11, 11}}, test::RobotKind::kPoint);
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  const PlanningContext ctx{*p.space, *p.environment, *checker, none};
  core::Rng rng(1);
  const core::StopCondition stop(kNoTimeLimit, 1000000);
  TrainingSettings s;
  s.nodes = 10;
  try {
    build_training_roadmap(ctx, s, stop, rng);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("no free configuration"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace amp::roadmap
