#include "amp/roadmap/uas/regional_sampler.hpp"

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "roadmap/test_worlds.hpp"

namespace amp::roadmap {
namespace {

// A sampler that always returns the same state, to see which region drew a sample.
class ConstantSampler final : public Sampler {
 public:
  explicit ConstantSampler(double x) : x_(x) {}
  bool sample(core::Rng&, State& out) override {
    out = test::state2(x_, 0);
    return true;
  }

 private:
  double x_;
};

TEST(RegionalSampler, TakesMSamplesFromEachRegionInTurn) {
  const world::Problem p = test::point_problem(true);
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  std::vector<std::unique_ptr<HybridSampler>> regions;
  for (int i = 0; i < 3; ++i) {
    std::vector<HybridSampler::Arm> arms;
    arms.push_back({"constant", std::make_unique<ConstantSampler>(i)});
    regions.push_back(std::make_unique<HybridSampler>(std::move(arms), *checker));
  }
  RegionalSampler s(std::move(regions), 4);
  core::Rng rng(1);
  State q;
  std::vector<int> drawn;
  for (int i = 0; i < 24; ++i) {
    ASSERT_TRUE(s.sample(rng, q));
    s.reward_last(Insertion{0, false, 2, 2, 1});
    drawn.push_back(static_cast<int>(q[0]));
  }
  for (int i = 0; i < 24; ++i) EXPECT_EQ(drawn[static_cast<std::size_t>(i)], (i / 4) % 3) << i;
  std::map<std::string, double> extra;
  s.report(extra);
  EXPECT_EQ(extra.at("samples_constant"), 24.0);
  EXPECT_EQ(extra.at("region1_rounds"), 2.0);
  EXPECT_THROW(RegionalSampler({}, 4), ParameterError);
}

TEST(RegionalSampler, WeightedScheduleServesRegionsInProportionAndInAFixedOrder) {
  const world::Problem p = test::point_problem(true);
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  auto regions = [&] {
    std::vector<std::unique_ptr<HybridSampler>> out;
    for (int i = 0; i < 2; ++i) {
      std::vector<HybridSampler::Arm> arms;
      arms.push_back({"constant", std::make_unique<ConstantSampler>(i)});
      out.push_back(std::make_unique<HybridSampler>(std::move(arms), *checker));
    }
    return out;
  };
  // Weights 3 and 1, smooth weighted round robin by hand: credits (3,1) -> 0 serves, (-1,1);
  // (2,2) -> 0 (ties: the first), (-2,2); (1,3) -> 1, (1,-1); (4,0) -> 0, (0,0): then it repeats.
  RegionalSampler s(regions(), 2, RegionSchedule::kWeighted, 0.5, {3.0, 1.0});
  core::Rng rng(1);
  State q;
  std::vector<int> drawn;
  for (int i = 0; i < 16; ++i) {
    ASSERT_TRUE(s.sample(rng, q));
    drawn.push_back(static_cast<int>(q[0]));
  }
  const std::vector<int> round_order = {0, 0, 1, 0};
  for (int i = 0; i < 16; ++i) EXPECT_EQ(drawn[static_cast<std::size_t>(i)], round_order[(i / 2) % 4]) << i;
  EXPECT_THROW(RegionalSampler(regions(), 2, RegionSchedule::kWeighted, 0.5, {1.0}), ParameterError);
  EXPECT_THROW(RegionalSampler(regions(), 2, RegionSchedule::kWeighted, 0.5, {1.0, 0.0}), ParameterError);
}

}  // namespace
}  // namespace amp::roadmap
