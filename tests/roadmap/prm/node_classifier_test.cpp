#include "amp/roadmap/prm/node_classifier.hpp"

#include <map>
#include <string>

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "amp/roadmap/prm/prm.hpp"
#include "roadmap/test_worlds.hpp"

namespace amp::roadmap {
namespace {

Insertion make(std::size_t attempts, std::size_t successes, std::size_t joined) {
  return Insertion{0, false, attempts, successes, joined};
}

TEST(NodeClassifier, ClassesByComponentsJoinedAndVisibility) {
  EXPECT_EQ(classify(make(0, 0, 0)), NodeClass::kCreate);  // the first node of a roadmap
  EXPECT_EQ(classify(make(5, 0, 0)), NodeClass::kCreate);
  EXPECT_EQ(classify(make(5, 2, 2)), NodeClass::kMerge);
  EXPECT_EQ(classify(make(5, 5, 3)), NodeClass::kMerge);
  EXPECT_EQ(classify(make(5, 2, 1)), NodeClass::kExpand);      // visibility 0.4 < 0.5
  EXPECT_EQ(classify(make(4, 2, 1)), NodeClass::kOversample);  // 0.5 is not "most" failing
  EXPECT_EQ(classify(make(5, 5, 1)), NodeClass::kOversample);
  EXPECT_DOUBLE_EQ(make(0, 0, 0).visibility(), 1.0);
  EXPECT_DOUBLE_EQ(make(4, 1, 1).visibility(), 0.25);
  EXPECT_EQ(to_string(NodeClass::kOversample), "cc_oversample");
}

// Returns its script, in order; fails once it runs out.
class ScriptedSampler final : public Sampler {
 public:
  explicit ScriptedSampler(std::vector<State> script) : script_(std::move(script)) {}
  bool sample(core::Rng&, State& out) override {
    if (next_ == script_.size()) return false;
    out = script_[next_++];
    return true;
  }

 private:
  std::vector<State> script_;
  std::size_t next_ = 0;
};

class Recorder final : public InsertionObserver {
 public:
  explicit Recorder(std::vector<Insertion>* out) : out_(out) {}
  void inserted(const Roadmap& roadmap, const Insertion& i) override {
    counter_.inserted(roadmap, i);
    out_->push_back(i);
  }
  void report(std::map<std::string, double>& extra) const override { counter_.report(extra); }

 private:
  std::vector<Insertion>* out_;
  NodeClassCounter counter_;
};

// The gap wall x in [4.5, 5.5] (gap 4.6 < y < 5.4), and a closed pen in the corner x, y > 8 holding the
// second seed, so the run never solves and ends at the node limit after the five scripted samples.
// With k = 10 every earlier node is tried; the expected outcome of every edge was worked out by hand:
//   a (9,2): to s0 through the lower wall, to the pen through its wall           -> 0/2, cc-create
//   b (2,2): s0 yes; a, pen no                                                   -> 1/3, 1 comp, cc-expand
//   c (3,5): s0, b yes; a (crosses x=4.5 at y=4.25), pen (y=6.04 there) no       -> 2/4, cc-oversample
//   d (8,5): a yes, c yes (y = 5 through the gap); s0, b, pen no                 -> 2/5, 2 comps, cc-merge
//   e (7,6): d, a yes; c, s0, b (cross x=4.5 below or above the gap), pen no     -> 2/6, 1 comp, cc-expand
TEST(NodeClassifier, PrmReportsTheClassesOfAHandBuiltRoadmap) {
  world::Problem p;
  p.space = std::make_shared<core::JointSpace>(core::make_rn_space({0, 0}, {10, 10}));
  p.environment = std::make_shared<test::BoxEnvironment>(
      std::vector<test::Box>{{4.5, 0, 5.5, 4.6}, {4.5, 5.4, 5.5, 10}, {8, 8, 8.2, 10}, {8, 8, 10, 8.2}},
      test::RobotKind::kPoint);
  p.seeds = {test::state2(1, 2), test::state2(9.5, 9.5)};
  const std::vector<State> script = {test::state2(9, 2), test::state2(2, 2), test::state2(3, 5), test::state2(8, 5),
                                     test::state2(7, 6)};
  std::vector<Insertion> seen;
  PrmParts parts;
  parts.sampler = [&](const PlanningContext&) { return std::make_unique<ScriptedSampler>(script); };
  parts.observer = [&](const PlanningContext&) { return std::make_unique<Recorder>(&seen); };

  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  const PlanningContext ctx{*p.space, *p.environment, *checker, p.seeds};
  core::Rng rng(1);
  const core::StopCondition stop(1e6, 7);
  const PlanResult r = Prm({}, parts).plan(ctx, stop, rng);
  ASSERT_EQ(r.status, core::PlanStatus::kNodeLimit);
  ASSERT_EQ(seen.size(), 7u);
  EXPECT_TRUE(seen[0].seed && seen[1].seed);
  EXPECT_EQ(seen[1].attempts, 1u);
  EXPECT_EQ(seen[1].successes, 0u);
  const std::vector<NodeClass> expected = {NodeClass::kCreate, NodeClass::kExpand, NodeClass::kOversample,
                                           NodeClass::kMerge, NodeClass::kExpand};
  const std::vector<std::size_t> successes = {0, 1, 2, 2, 2}, joined = {0, 1, 1, 2, 1};
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const Insertion& in = seen[i + 2];
    EXPECT_FALSE(in.seed);
    EXPECT_EQ(in.attempts, i + 2) << i;  // every earlier node is a candidate
    EXPECT_EQ(in.successes, successes[i]) << i;
    EXPECT_EQ(in.components_joined, joined[i]) << i;
    EXPECT_EQ(classify(in), expected[i]) << i;
  }
  EXPECT_EQ(r.extra.at("cc_create"), 1.0);
  EXPECT_EQ(r.extra.at("cc_merge"), 1.0);
  EXPECT_EQ(r.extra.at("cc_expand"), 2.0);
  EXPECT_EQ(r.extra.at("cc_oversample"), 1.0);
  EXPECT_EQ(r.components, 2u);  // everything but the pen
}

TEST(NodeClassifier, ObservingChangesNothingInTheRun) {
  const world::Problem p = test::point_problem(true);
  auto run = [&](bool observe, std::uint64_t& cd) {
    PrmParts parts;
    if (observe) parts.observer = [](const PlanningContext&) { return std::make_unique<NodeClassCounter>(); };
    core::Counters counters;
    const auto checker = p.environment->make_checker(counters);
    const PlanningContext ctx{*p.space, *p.environment, *checker, p.seeds};
    core::Rng rng(17);
    const core::StopCondition stop(1e6, 5000);
    PlanResult r = Prm({}, parts).plan(ctx, stop, rng);
    cd = counters.cd_calls();
    return r;
  };
  std::uint64_t cd_plain = 0, cd_observed = 0;
  const PlanResult plain = run(false, cd_plain), observed = run(true, cd_observed);
  ASSERT_EQ(plain.status, core::PlanStatus::kSolved);
  EXPECT_EQ(plain.path, observed.path);
  EXPECT_EQ(cd_plain, cd_observed);
  EXPECT_EQ(plain.edges, observed.edges);
  EXPECT_EQ(plain.extra.count("cc_create"), 0u);
  const double classified = observed.extra.at("cc_create") + observed.extra.at("cc_merge") +
                            observed.extra.at("cc_expand") + observed.extra.at("cc_oversample");
  EXPECT_EQ(classified, static_cast<double>(observed.nodes - p.seeds.size()));  // every sample, no seed
  EXPECT_GE(observed.extra.at("cc_merge"), 1.0);  // the gap sample that joined the sides
}

}  // namespace
}  // namespace amp::roadmap
