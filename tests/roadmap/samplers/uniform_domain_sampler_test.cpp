// samplers/uniform_domain_sampler.cpp: free states uniform in a domain, by rejection.
#include "amp/roadmap/samplers/uniform_domain_sampler.hpp"

#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "amp/roadmap/samplers/uniform_sampler.hpp"
#include "roadmap/test_worlds.hpp"

namespace amp::roadmap {
namespace {

TEST(UniformDomainSampler, OnTheWholeSpaceDrawsWhatUniformSamplerDraws) {
  const world::Problem p = test::point_problem(true);
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  UniformSampler a(*p.space, *checker);
  UniformDomainSampler b(std::make_shared<WholeSpaceDomain>(*p.space), *checker);
  core::Rng ra(4), rb(4);
  State qa, qb;
  for (int i = 0; i < 50; ++i) {
    ASSERT_EQ(a.sample(ra, qa), b.sample(rb, qb));
    EXPECT_EQ(qa, qb);
  }
}

// A box across the wall x in [4.5, 5.5]: samples are free and in the box, so left or right of the
// wall (or in its gap), in proportion to the free areas.
TEST(UniformDomainSampler, InABoxSamplesAreFreeAndInsideIt) {
  const world::Problem p = test::point_problem(true);
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  const auto box = std::make_shared<ReferencePointBoxDomain>(
      *p.space, *p.environment, Eigen::AlignedBox3d(Eigen::Vector3d(4, 1, 0), Eigen::Vector3d(6, 3, 0)));
  UniformDomainSampler u(box, *checker);
  core::Rng rng(5);
  State q;
  int left = 0;
  constexpr int kDraws = 2000;
  for (int i = 0; i < kDraws; ++i) {
    ASSERT_TRUE(u.sample(rng, q));
    EXPECT_TRUE(box->contains(q));
    EXPECT_TRUE(q[0] < 4.5 || q[0] > 5.5) << q.transpose();  // no gap at y in [1, 3]
    left += q[0] < 4.5;
  }
  EXPECT_NEAR(static_cast<double>(left) / kDraws, 0.5, 0.05);  // free strips of equal width
  // One CD call per draw, and half the box is wall: about two draws per sample (4000 +- 63).
  EXPECT_GT(counters.cd_calls(), 3600u);
  EXPECT_LT(counters.cd_calls(), 4400u);
}

// Inside an obstacle nothing is free: max_attempts draws, one CD call each, and no sample.
TEST(UniformDomainSampler, InsideAnObstacleGivesUpAfterMaxAttempts) {
  const world::Problem p = test::point_problem(true);
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  const auto in_wall = std::make_shared<ReferencePointBoxDomain>(
      *p.space, *p.environment, Eigen::AlignedBox3d(Eigen::Vector3d(4.6, 1, 0), Eigen::Vector3d(5.4, 3, 0)));
  UniformDomainSampler u(in_wall, *checker, 13);
  core::Rng rng(1);
  State q;
  EXPECT_FALSE(u.sample(rng, q));
  EXPECT_EQ(counters.cd_calls(), 13u);
}

}  // namespace
}  // namespace amp::roadmap
