// What the obstacle-based samplers share (Gaussian, OBPRM, bridge: one typed suite), and their
// settings checks. Each sampler's own behaviour is in <name>_sampler_test.cpp, the domains they draw
// from in sampling_domain_test.cpp.
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/roadmap/samplers/bridge_sampler.hpp"
#include "amp/roadmap/samplers/gaussian_sampler.hpp"
#include "amp/roadmap/samplers/obprm_sampler.hpp"
#include "amp/roadmap/samplers/random_offset.hpp"
#include "amp/roadmap/samplers/sampling_domain.hpp"
#include "amp/roadmap/samplers/uniform_sampler.hpp"
#include "amp/world/problem.hpp"
#include "roadmap/test_worlds.hpp"
#include "support/source_tree.hpp"

namespace amp::roadmap {
namespace {

const world::Problem& walls() {
  static const world::Problem p = world::load_problem(std::string(AMP_SOURCE_DIR) + "/problems/walls.yaml");
  return p;
}


struct Gaussian {
  static std::unique_ptr<Sampler> make(const world::Problem& p, const world::ValidityChecker& c,
                                       std::shared_ptr<const SamplingDomain> domain = nullptr) {
    return std::make_unique<GaussianSampler>(*p.space, c,
                                             GaussianSamplerSettings{sampler_distance(*p.environment, *p.space, 1).d, 100},
                                             std::move(domain));
  }
};
struct Obprm {
  static std::unique_ptr<Sampler> make(const world::Problem& p, const world::ValidityChecker& c,
                                       std::shared_ptr<const SamplingDomain> domain = nullptr) {
    return std::make_unique<ObprmSampler>(*p.space, c, ObprmSamplerSettings{}, std::move(domain));
  }
};
struct Bridge {
  static std::unique_ptr<Sampler> make(const world::Problem& p, const world::ValidityChecker& c,
                                       std::shared_ptr<const SamplingDomain> domain = nullptr) {
    BridgeSamplerSettings b;
    b.d = sampler_distance(*p.environment, *p.space, 2).d;
    b.max_attempts = 1000;
    return std::make_unique<BridgeSampler>(*p.space, c, b, std::move(domain));
  }
};

template <class T>
class ObstacleSampler : public ::testing::Test {};
using Kinds = ::testing::Types<Gaussian, Obprm, Bridge>;
TYPED_TEST_SUITE(ObstacleSampler, Kinds);

constexpr int kSamples = 150;

// Draws kSamples samples; returns the states and the CD calls they cost.
std::vector<State> draw(const world::Problem& p, std::unique_ptr<Sampler> (*make)(const world::Problem&, const world::ValidityChecker&, std::shared_ptr<const SamplingDomain>),
                        std::uint64_t seed, std::uint64_t& cd_calls, std::shared_ptr<const SamplingDomain> domain = nullptr) {
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  auto sampler = make(p, *checker, std::move(domain));
  core::Rng rng(seed);
  std::vector<State> out;
  State q;
  for (int i = 0; i < kSamples; ++i) {
    if (sampler->sample(rng, q)) out.push_back(q);
  }
  cd_calls = counters.cd_calls();
  return out;
}

TYPED_TEST(ObstacleSampler, SamplesAreFreeInBoundsAndCountedAndSeedDeterministic) {
  const world::Problem& p = walls();
  std::uint64_t cd_a = 0, cd_b = 0, cd_c = 0;
  const std::vector<State> a = draw(p, &TypeParam::make, 11, cd_a);
  const std::vector<State> b = draw(p, &TypeParam::make, 11, cd_b);
  const std::vector<State> c = draw(p, &TypeParam::make, 12, cd_c);
  ASSERT_GE(a.size(), static_cast<std::size_t>(kSamples * 9 / 10));
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  for (const State& s : a) {
    EXPECT_TRUE(p.space->in_bounds(s));
    EXPECT_TRUE(checker->is_valid(s));  // an independent checker agrees
  }
  EXPECT_EQ(a, b);
  EXPECT_EQ(cd_a, cd_b);
  EXPECT_NE(a, c);
  EXPECT_GT(cd_a, a.size());  // each sample spent more than the one check a uniform free draw needs
}

TYPED_TEST(ObstacleSampler, SamplesLieCloserToObstaclesThanUniformOnes) {
  const world::Problem& p = walls();
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  // The workspace border is an obstacle to the samplers too (a pose across it collides), but not to
  // clearance(): count the robot centre's distance to the border as well.
  const Eigen::AlignedBox3d border = p.environment->workspace_bounds();
  auto mean_clearance = [&](const std::vector<State>& states) {
    double sum = 0.0;
    for (const State& s : states) {
      const double to_border = std::min({s[0] - border.min().x(), border.max().x() - s[0], s[1] - border.min().y(),
                                         border.max().y() - s[1]});
      sum += std::min(checker->clearance(s).distance, to_border);
    }
    return sum / static_cast<double>(states.size());
  };
  std::uint64_t cd = 0;
  const double near = mean_clearance(draw(p, &TypeParam::make, 3, cd));
  UniformSampler uniform(*p.space, *checker);
  core::Rng rng(3);
  std::vector<State> u;
  State q;
  while (u.size() < static_cast<std::size_t>(kSamples)) {
    if (uniform.sample(rng, q)) u.push_back(q);
  }
  const double far = mean_clearance(u);
  // Uniform samples of Walls sit about 5 units from an obstacle or the border; near-surface ones far less.
  EXPECT_LT(near, 0.5 * far) << "obstacle-based " << near << " vs uniform " << far;
}

TYPED_TEST(ObstacleSampler, RegionSamplesStayInTheRegion) {
  const world::Problem& p = walls();
  // The middle chamber's doorway area around the wall x = 30, 25 < y < 45.
  const Eigen::AlignedBox3d box(Eigen::Vector3d(25, 25, 0), Eigen::Vector3d(35, 45, 0));
  const auto domain = std::make_shared<ReferencePointBoxDomain>(*p.space, *p.environment, box);
  std::uint64_t cd = 0;
  const std::vector<State> s = draw(p, &TypeParam::make, 5, cd, domain);
  ASSERT_GE(s.size(), static_cast<std::size_t>(kSamples / 2));
  for (const State& q : s) {
    const Eigen::Vector3d r = p.environment->reference_point(q);
    EXPECT_TRUE(r.x() >= 25 && r.x() <= 35 && r.y() >= 25 && r.y() <= 45) << r.transpose();
  }
}

TEST(ObstacleSamplers, RejectBadSettings) {
  EXPECT_THROW(GaussianSamplerSettings({0.0, 10}).validate(), ParameterError);
  EXPECT_THROW(GaussianSamplerSettings({1.0, 0}).validate(), ParameterError);
  EXPECT_THROW(ObprmSamplerSettings({10, 0}).validate(), ParameterError);
  BridgeSamplerSettings b;
  b.uniform_mix = 1.5;
  EXPECT_THROW(b.validate(), ParameterError);
}

}  // namespace
}  // namespace amp::roadmap
