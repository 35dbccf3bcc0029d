// samplers/sampling_domain.cpp: where samplers draw their uniform states, the whole space or a box
// over the robot's reference point, at random or from a Halton sequence.
#include "amp/roadmap/samplers/sampling_domain.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "roadmap/test_worlds.hpp"

namespace amp::roadmap {
namespace {

TEST(SamplingDomain, ReferencePointBoxIsUniformOverItsBox) {
  const world::Problem p = test::point_problem(true);
  const ReferencePointBoxDomain domain(*p.space, *p.environment,
                                       Eigen::AlignedBox3d(Eigen::Vector3d(2, 6, 0), Eigen::Vector3d(4, 7, 0)));
  core::Rng rng(2);
  State s;
  double mx = 0.0, my = 0.0;
  constexpr int kDraws = 4000;
  for (int i = 0; i < kDraws; ++i) {
    ASSERT_TRUE(domain.sample(rng, s));
    ASSERT_TRUE(domain.contains(s));
    mx += s[0];
    my += s[1];
  }
  EXPECT_NEAR(mx / kDraws, 3.0, 0.05);
  EXPECT_NEAR(my / kDraws, 6.5, 0.03);
  EXPECT_FALSE(domain.contains(test::state2(5, 5)));
  EXPECT_THROW(ReferencePointBoxDomain(*p.space, *p.environment,
                                       Eigen::AlignedBox3d(Eigen::Vector3d(4, 6, 0), Eigen::Vector3d(2, 7, 0))),
               ParameterError);
}

TEST(SamplingDomain, HaltonBoxDrawsStayInTheBoxRepeatAndFillItEvenly) {
  const world::Problem p = test::point_problem(true);
  const Eigen::AlignedBox3d box(Eigen::Vector3d(2, 6, 0), Eigen::Vector3d(4, 7, 0));
  const ReferencePointBoxDomain a(*p.space, *p.environment, box, DrawSequence::kHalton);
  const ReferencePointBoxDomain b(*p.space, *p.environment, box, DrawSequence::kHalton);
  core::Rng ra(2), rb(2);
  // 512 draws on an 8 x 8 grid over the box (8 expected per cell). Pearson's statistic of the cell
  // counts is chi-square with 63 degrees of freedom for independent draws (mean 63; below 31.5 with
  // probability 3e-4); an even cover keeps it far lower.
  constexpr int kSide = 8, kDraws = 512;
  std::vector<int> cells(kSide * kSide, 0);
  State s, t;
  for (int i = 0; i < kDraws; ++i) {
    ASSERT_TRUE(a.sample(ra, s));
    ASSERT_TRUE(b.sample(rb, t));
    ASSERT_EQ(s, t);
    ASSERT_TRUE(a.contains(s));
    const int cx = std::min(kSide - 1, static_cast<int>((s[0] - 2.0) / 2.0 * kSide));
    const int cy = std::min(kSide - 1, static_cast<int>((s[1] - 6.0) / 1.0 * kSide));
    ++cells[static_cast<std::size_t>(cx * kSide + cy)];
  }
  const double expected = static_cast<double>(kDraws) / (kSide * kSide);
  double chi2 = 0.0;
  for (const int c : cells) chi2 += (c - expected) * (c - expected) / expected;
  EXPECT_LT(chi2, 31.5);
  EXPECT_EQ(parse_draw_sequence("halton"), DrawSequence::kHalton);
  EXPECT_EQ(parse_draw_sequence("random"), DrawSequence::kRandom);
  EXPECT_THROW(parse_draw_sequence("sobol"), ParameterError);
}

// The arm's reference point is its tip: the box constrains forward kinematics, recomputed here.
TEST(SamplingDomain, ArmDrawsPutTheTipInTheBox) {
  const world::Problem p = test::arm_problem();
  const Eigen::AlignedBox3d box(Eigen::Vector3d(6, 6, -1), Eigen::Vector3d(8, 8, 1));
  const ReferencePointBoxDomain domain(*p.space, *p.environment, box);
  const auto tip = [](const State& s) {
    const Eigen::Vector2d elbow = test::kArmBase + test::kArmLink * Eigen::Vector2d(std::cos(s[0]), std::sin(s[0]));
    return Eigen::Vector2d(elbow + test::kArmLink * Eigen::Vector2d(std::cos(s[0] + s[1]), std::sin(s[0] + s[1])));
  };
  core::Rng rng(3);
  State s;
  for (int i = 0; i < 500; ++i) {
    ASSERT_TRUE(domain.sample(rng, s));
    const Eigen::Vector2d t = tip(s);
    EXPECT_TRUE(t.x() >= 6 - 1e-9 && t.x() <= 8 + 1e-9 && t.y() >= 6 - 1e-9 && t.y() <= 8 + 1e-9) << t.transpose();
    EXPECT_TRUE(p.space->in_bounds(s));
  }
  // contains() agrees with the kinematics on random states of the whole space.
  int inside = 0;
  for (int i = 0; i < 2000; ++i) {
    p.space->sample_uniform(rng, s);
    const Eigen::Vector2d t = tip(s);
    const bool want = t.x() >= 6 && t.x() <= 8 && t.y() >= 6 && t.y() <= 8;
    EXPECT_EQ(domain.contains(s), want) << s.transpose();
    inside += want;
  }
  EXPECT_GT(inside, 20);
  // Out of the arm's reach (4 from its base at (5, 5)): sample() gives up after kMaxDraws draws.
  const ReferencePointBoxDomain unreachable(*p.space, *p.environment,
                                            Eigen::AlignedBox3d(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.5, 0.5, 0)));
  EXPECT_FALSE(unreachable.sample(rng, s));
}

TEST(SamplingDomain, WholeSpaceDrawsWhatTheSpaceDrawsAndNullStandsForIt) {
  const world::Problem p = test::point_problem(true);
  const WholeSpaceDomain whole(*p.space);
  core::Rng a(12), b(12);
  State s, t;
  for (int i = 0; i < 100; ++i) {
    ASSERT_TRUE(whole.sample(a, s));
    p.space->sample_uniform(b, t);
    EXPECT_EQ(s, t);
    EXPECT_TRUE(whole.contains(s));
  }
  EXPECT_FALSE(whole.contains(test::state2(11, 5)));
  const auto given = std::make_shared<WholeSpaceDomain>(*p.space);
  EXPECT_EQ(domain_or_whole(given, *p.space), given);
  const auto made = domain_or_whole(nullptr, *p.space);
  ASSERT_NE(made, nullptr);
  EXPECT_NE(dynamic_cast<const WholeSpaceDomain*>(made.get()), nullptr);
}

}  // namespace
}  // namespace amp::roadmap
