#include "amp/nav/sins/motor_schemas.hpp"

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/core/rng.hpp"

namespace amp::nav {
namespace {

using V = Eigen::Vector2d;

TEST(MotorSchemas, EachSchemaByHand) {
  // Sphere 2 m, margin 0.1 m, no speed cap in the way.
  SchemaSettings s;
  s.max_speed = 100.0;
  MotorSchemas schemas(s);
  SchemaParameters p{2.0, 1.5, 0.0, 5.0};
  core::Rng rng(1);
  // Two readings: ahead (+x) at 1.05 m, repelling 2 (2 - 1.05) / (2 - 0.1) = 1 along -x; left (+y)
  // at 0.05 m (inside the margin), repelling 2 along -y; a third beyond the sphere, nothing.
  const std::vector<double> readings = {1.05, 0.05, 2.5};
  const std::vector<V> directions = {V(1, 0), V(0, 1), V(-1, 0)};
  const V v = schemas.velocity(V(0, 0), V(3, 4), readings, directions, p, rng);
  EXPECT_NEAR(schemas.last_avoid().x(), -1.0, 1e-12);
  EXPECT_NEAR(schemas.last_avoid().y(), -2.0, 1e-12);
  // MOVE-TO-GOAL: 1.5 toward (3, 4) / 5.
  EXPECT_NEAR(schemas.last_goal().x(), 0.9, 1e-12);
  EXPECT_NEAR(schemas.last_goal().y(), 1.2, 1e-12);
  EXPECT_EQ(schemas.last_noise(), V::Zero());
  EXPECT_NEAR(v.x(), -0.1, 1e-12);
  EXPECT_NEAR(v.y(), -0.8, 1e-12);
}

TEST(MotorSchemas, NoiseIsHeldForItsPersistenceAndTheSumIsClipped) {
  MotorSchemas schemas;  // max_speed 1 m per step
  SchemaParameters p{0.0, 0.0, 0.8, 3.0};
  core::Rng rng(7), same(7);
  const std::vector<double> none;
  const std::vector<V> no_dirs;
  std::vector<V> noise;
  for (int i = 0; i < 7; ++i) {
    schemas.velocity(V(0, 0), V(1, 0), none, no_dirs, p, rng);
    noise.push_back(schemas.last_noise());
  }
  // Directions drawn at steps 0, 3 and 6, from the same stream: 0.8 (cos a, sin a).
  for (int draw : {0, 3, 6}) {
    const double a = same.uniform(0.0, 2.0 * std::numbers::pi);
    EXPECT_NEAR(noise[draw].x(), 0.8 * std::cos(a), 1e-12);
    EXPECT_NEAR(noise[draw].y(), 0.8 * std::sin(a), 1e-12);
  }
  EXPECT_EQ(noise[1], noise[0]);
  EXPECT_EQ(noise[2], noise[0]);
  EXPECT_EQ(noise[4], noise[3]);
  EXPECT_NE(noise[3], noise[0]);
  // Goal 2 + noise 1 point the same way at most: clipped to 1 m per step.
  SchemaParameters strong{0.0, 2.0, 1.0, 1.0};
  const V v = schemas.velocity(V(0, 0), V(1, 0), none, no_dirs, strong, rng);
  EXPECT_NEAR(v.norm(), 1.0, 1e-12);
}

TEST(MotorSchemas, RangesNormaliseBothWaysAndBadValuesGetOneLine) {
  const SchemaParameters mid = SchemaParameters::middle();
  EXPECT_DOUBLE_EQ(mid.obstacle_gain, 2.5);
  EXPECT_DOUBLE_EQ(mid.goal_gain, 1.0);
  EXPECT_DOUBLE_EQ(mid.noise_gain, 0.5);
  EXPECT_DOUBLE_EQ(mid.noise_persistence, 10.5);
  const SchemaParameters p{1.0, 0.5, 0.25, 20.0};
  const auto u = p.normalised();
  EXPECT_DOUBLE_EQ(u[0], 0.2);
  EXPECT_DOUBLE_EQ(u[1], 0.25);
  EXPECT_DOUBLE_EQ(u[2], 0.25);
  EXPECT_DOUBLE_EQ(u[3], 1.0);
  const SchemaParameters back = SchemaParameters::from_normalised({0.2, 0.25, 0.25, 1.5});
  EXPECT_DOUBLE_EQ(back.obstacle_gain, 1.0);
  EXPECT_DOUBLE_EQ(back.noise_persistence, 20.0);  // clamped
  auto message = [](SchemaParameters q) {
    try {
      q.validate();
    } catch (const ParameterError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message({6.0, 1.0, 0.5, 5.0}).find("obstacle_gain"), std::string::npos);
  EXPECT_NE(message({1.0, -1.0, 0.5, 5.0}).find("goal_gain"), std::string::npos);
  EXPECT_NE(message({1.0, 1.0, 0.5, 0.0}).find("noise_persistence"), std::string::npos);
  EXPECT_EQ(message(mid), "no error");
  SchemaSettings bad;
  bad.sphere_of_influence = 0.05;
  EXPECT_THROW(MotorSchemas{bad}, ParameterError);
}

}  // namespace
}  // namespace amp::nav
