#include "amp/core/se3_space.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace amp::core {
namespace {

constexpr double kPi = std::numbers::pi;

State pose(double x, double y, double z, const Eigen::Quaterniond& q) {
  return Se3Space::make_state({x, y, z}, q);
}

Eigen::Quaterniond about_z(double a) { return Eigen::Quaterniond(Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ())); }

TEST(Se3Space, DistanceIsWeightedTranslationPlusRotationAngle) {
  const Se3Space s({0, 0, 0}, {10, 10, 10}, 2.0);
  EXPECT_NEAR(s.distance(pose(0, 0, 0, about_z(0)), pose(3, 4, 0, about_z(0))), 5.0, 1e-12);
  EXPECT_NEAR(s.distance(pose(1, 1, 1, about_z(0)), pose(1, 1, 1, about_z(0.5))), 2.0 * 0.5, 1e-9);
  // q and -q are one rotation.
  State a = pose(1, 1, 1, about_z(0.3));
  State b = a;
  b.tail<4>() *= -1.0;
  EXPECT_NEAR(s.distance(a, b), 0.0, 1e-6);
}

TEST(Se3Space, SlerpTakesTheShortArcAndEndsExactly) {
  const Se3Space s({0, 0, 0}, {10, 10, 10}, 1.0);
  const State a = pose(0, 0, 0, about_z(0.2));
  State b = pose(2, 0, 0, about_z(-0.4));
  b.tail<4>() *= -1.0;  // same rotation, other hemisphere
  State mid;
  s.interpolate(a, b, 0.5, mid);
  EXPECT_NEAR(mid[0], 1.0, 1e-12);
  EXPECT_NEAR(s.distance(mid, pose(1, 0, 0, about_z(-0.1))), 0.0, 1e-6);
  s.interpolate(a, b, 1.0, mid);
  EXPECT_NEAR(s.distance(mid, b), 0.0, 1e-6);
}

TEST(Se3Space, UniformSamplesAreUnitQuaternionsInBounds) {
  const Se3Space s({-1, -2, -3}, {1, 2, 3}, 1.0);
  Rng rng(11);
  double mean_abs_w = 0.0;
  constexpr int kN = 20000;
  for (int i = 0; i < kN; ++i) {
    State x;
    s.sample_uniform(rng, x);
    ASSERT_TRUE(s.in_bounds(x));
    mean_abs_w += std::abs(x[6]);
  }
  // Uniform on S^3, w has density (2/pi) sqrt(1 - w^2), so E|w| = 4/(3 pi) = 0.4244.
  EXPECT_NEAR(mean_abs_w / kN, 4.0 / (3.0 * kPi), 0.01);
}

TEST(Se3Space, EmbeddingOverBothSignsIsALowerBound) {
  const Se3Space s({0, 0, 0}, {1, 1, 1}, 0.7, 1.3);
  Rng rng(5);
  for (int i = 0; i < 5000; ++i) {
    State a, b;
    s.sample_uniform(rng, a);
    s.sample_uniform(rng, b);
    double ea[7], eb[7];
    s.embed(b, eb);
    double best = 1e300;
    for (int v = 0; v < s.embedding_variants(); ++v) {
      s.embed_variant(a, v, ea);
      double sq = 0;
      for (int j = 0; j < 7; ++j) sq += (ea[j] - eb[j]) * (ea[j] - eb[j]);
      best = std::min(best, std::sqrt(sq));
    }
    ASSERT_LE(best, s.distance(a, b) + 1e-12);
  }
}

}  // namespace
}  // namespace amp::core
