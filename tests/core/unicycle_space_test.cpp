#include "amp/core/unicycle_space.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"

namespace amp::core {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();

using U = UnicycleSpace;

UnicycleBounds box() {
  return {.x_min = 0, .x_max = 10, .y_min = 0, .y_max = 10, .v_min = -1, .v_max = 2, .omega_min = -1,
          .omega_max = 1};
}

TEST(UnicycleSpace, DescribesItselfAsAFiveCoordinateSpace) {
  const UnicycleSpace s(box());
  const Space& base = s;
  EXPECT_EQ(base.kind(), "unicycle");
  EXPECT_EQ(base.dimension(), 5);
  EXPECT_EQ(base.dof(), 5);
  EXPECT_EQ(base.unit_dimension(), 5);
  EXPECT_EQ(base.embedding_dimension(), 6);
  EXPECT_EQ(s.weights().theta, 1.0);  // documented defaults
  EXPECT_EQ(s.weights().v, 1.0);
  EXPECT_EQ(s.weights().omega, 1.0);
}

TEST(UnicycleSpace, DistanceGoesTheShortWayAcrossThePiSeam) {
  const UnicycleSpace s(box(), {.theta = 2.0});
  // 3.1 and -3.1 are 2pi - 6.2 = 0.0832 rad apart across +-pi, not 6.2; times w_theta = 2.
  EXPECT_NEAR(s.distance(U::make_state(1, 1, 3.1, 0, 0), U::make_state(1, 1, -3.1, 0, 0)), 2.0 * (2 * kPi - 6.2),
              1e-12);
  // pi and -pi are one heading; so are theta and theta + 2pi.
  EXPECT_NEAR(s.distance(U::make_state(1, 1, kPi, 0, 0), U::make_state(1, 1, -kPi, 0, 0)), 0.0, 1e-12);
  EXPECT_NEAR(s.distance(U::make_state(2, 2, 0.5, 0, 0), U::make_state(2, 2, 0.5 + 2 * kPi, 0, 0)), 0.0, 1e-12);
  // Antipodal headings are the farthest apart: w_theta * pi.
  EXPECT_NEAR(s.distance(U::make_state(1, 1, 0.5, 0, 0), U::make_state(1, 1, 0.5 - kPi, 0, 0)), 2.0 * kPi, 1e-12);
}

TEST(UnicycleSpace, DistanceWeighsEveryCoordinate) {
  const UnicycleSpace s(box(), {.theta = 4.0, .v = 8.0, .omega = 10.0});
  // dx = 1, dy = 2, w_theta * dtheta = 4 * 0.5 = 2, w_v * dv = 8 * 0.25 = 2, w_omega * domega = 10 * 0.4 = 4:
  // sqrt(1 + 4 + 4 + 4 + 16) = sqrt(29).
  EXPECT_NEAR(s.distance(U::make_state(1, 2, 0.25, 0.5, -0.2), U::make_state(2, 4, 0.75, 0.75, 0.2)), std::sqrt(29.0),
              1e-12);
  // Default weights of 1: sqrt(0.3^2 + 0.4^2) = 0.5 from theta and v alone.
  const UnicycleSpace unit(box());
  EXPECT_NEAR(unit.distance(U::make_state(3, 3, -0.1, 0, 0), U::make_state(3, 3, 0.2, 0.4, 0)), 0.5, 1e-12);
}

TEST(UnicycleSpace, InterpolationCrossesPiTheShortWay) {
  const UnicycleSpace s(box());
  const State a = U::make_state(0, 0, 3.0, 0, -1);
  const State b = U::make_state(2, 4, -3.0, 1, 1);
  const double gap = 2 * kPi - 6.0;  // 0.2832 rad counter-clockwise from 3.0 to -3.0
  State m;
  s.interpolate(a, b, 0.5, m);
  EXPECT_NEAR(m[U::kX], 1.0, 1e-12);
  EXPECT_NEAR(m[U::kY], 2.0, 1e-12);
  EXPECT_NEAR(std::abs(m[U::kTheta]), kPi, 1e-12);  // 3.0 + 0.1416 = pi: halfway is on the seam
  EXPECT_GT(m[U::kTheta], -kPi);
  EXPECT_LE(m[U::kTheta], kPi);
  EXPECT_NEAR(m[U::kV], 0.5, 1e-12);
  EXPECT_NEAR(m[U::kOmega], 0.0, 1e-12);
  s.interpolate(a, b, 0.25, m);
  EXPECT_NEAR(m[U::kTheta], 3.0 + 0.25 * gap, 1e-12);  // 3.0708, before the seam
  s.interpolate(a, b, 0.75, m);
  EXPECT_NEAR(m[U::kTheta], 3.0 + 0.75 * gap - 2 * kPi, 1e-12);  // 3.2124 wraps to -3.0708, past it
  // And back the other way: clockwise from -3.0 through -pi.
  s.interpolate(b, a, 0.25, m);
  EXPECT_NEAR(m[U::kTheta], -3.0 - 0.25 * gap, 1e-12);
  s.interpolate(b, a, 0.75, m);
  EXPECT_NEAR(m[U::kTheta], 3.0 + 0.25 * gap, 1e-12);
}

TEST(UnicycleSpace, InterpolationEndpointsAreExact) {
  const UnicycleSpace s(box());
  const State a = U::make_state(0.1, 0.7, 3.0, 0.3, -0.9);
  const State b = U::make_state(9.3, 0.2, -3.0, 1.7, 0.6);
  State m;
  s.interpolate(a, b, 0.0, m);
  EXPECT_EQ(m, a);
  s.interpolate(a, b, 1.0, m);
  EXPECT_EQ(m, b);
  // An endpoint's heading comes back wrapped into (-pi, pi]: -pi is pi, pi + 0.5 is -pi + 0.5.
  s.interpolate(a, U::make_state(9.3, 0.2, -kPi, 1.7, 0.6), 1.0, m);
  EXPECT_EQ(m, U::make_state(9.3, 0.2, kPi, 1.7, 0.6));
  s.interpolate(U::make_state(1, 1, kPi + 0.5, 0, 0), b, 0.0, m);
  EXPECT_NEAR(m[U::kTheta], -kPi + 0.5, 1e-12);
  // Writing into an endpoint is allowed.
  State c = a;
  s.interpolate(c, b, 0.5, c);
  EXPECT_NEAR(c[U::kX], 4.7, 1e-12);
}

TEST(UnicycleSpace, InterpolatedStatesLieOnTheGeodesic) {
  const UnicycleSpace s(box(), {.theta = 0.7, .v = 1.5, .omega = 0.4});
  Rng rng(17);
  for (int i = 0; i < 2000; ++i) {
    State a, b, m;
    s.sample_uniform(rng, a);
    s.sample_uniform(rng, b);
    const double t = rng.uniform01();
    s.interpolate(a, b, t, m);
    ASSERT_TRUE(s.in_bounds(m));
    const double d = s.distance(a, b);
    ASSERT_NEAR(s.distance(a, m), t * d, 1e-9);
    ASSERT_NEAR(s.distance(m, b), (1 - t) * d, 1e-9);
  }
}

TEST(UnicycleSpace, SamplesStayInBoundsCoverThemAndAreSeedDeterministic) {
  const UnicycleSpace s(box());
  Rng a(7), b(7), c(8);
  State lo = U::make_state(kInf, kInf, kInf, kInf, kInf), hi = -lo;
  bool differs = false;
  for (int i = 0; i < 20000; ++i) {
    State x, y, z;
    s.sample_uniform(a, x);
    s.sample_uniform(b, y);
    s.sample_uniform(c, z);
    ASSERT_TRUE(s.in_bounds(x));
    ASSERT_GT(x[U::kTheta], -kPi);
    ASSERT_LE(x[U::kTheta], kPi);
    ASSERT_EQ(x, y);
    differs = differs || x != z;
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  EXPECT_TRUE(differs);
  // 20000 uniform draws come within 0.1% of the range (x: 0.01) of each end, almost surely.
  const State want_lo = U::make_state(0, 0, -kPi, -1, -1), want_hi = U::make_state(10, 10, kPi, 2, 1);
  for (int i = 0; i < 5; ++i) {
    const double slack = 1e-3 * (want_hi[i] - want_lo[i]);
    EXPECT_NEAR(lo[i], want_lo[i], slack) << i;
    EXPECT_NEAR(hi[i], want_hi[i], slack) << i;
  }
  // u = 0 is the lower corner with heading -pi, i.e. pi.
  const double zeros[5] = {0, 0, 0, 0, 0};
  State x;
  s.from_unit(zeros, x);
  EXPECT_EQ(x, U::make_state(0, 0, kPi, -1, -1));
}

TEST(UnicycleSpace, BadBoundsAndWeightsAreRejectedByName) {
  const auto expect_error = [](const std::function<void(UnicycleBounds&, UnicycleWeights&, double&)>& edit,
                               const std::string& message) {
    UnicycleBounds bounds = box();
    UnicycleWeights weights;
    double fraction = 0.01;
    edit(bounds, weights, fraction);
    try {
      const UnicycleSpace s(bounds, weights, fraction);
      ADD_FAILURE() << "accepted; expected: " << message;
    } catch (const ParameterError& e) {
      EXPECT_EQ(std::string(e.what()), message);
    }
  };
  using B = UnicycleBounds;
  using W = UnicycleWeights;
  expect_error([](B& b, W&, double&) { b.x_min = 5; b.x_max = 1; },
               "unicycle bounds: x_min (5) must be below x_max (1)");
  expect_error([](B& b, W&, double&) { b.y_min = b.y_max = 2; }, "unicycle bounds: y_min (2) must be below y_max (2)");
  expect_error([](B& b, W&, double&) { b.v_max = kInf; }, "unicycle bounds: v_max must be finite, got inf");
  expect_error([](B& b, W&, double&) { b.omega_min = std::nan(""); },
               "unicycle bounds: omega_min must be finite, got nan");
  expect_error([](B& b, W&, double&) { b.omega_min = b.omega_max = 0; },  // an omitted pair
               "unicycle bounds: omega_min (0) must be below omega_max (0)");
  expect_error([](B&, W& w, double&) { w.theta = 0; }, "unicycle weights: theta must be positive and finite, got 0");
  expect_error([](B&, W& w, double&) { w.v = -1; }, "unicycle weights: v must be positive and finite, got -1");
  expect_error([](B&, W& w, double&) { w.omega = kInf; },
               "unicycle weights: omega must be positive and finite, got inf");
  expect_error([](B&, W&, double& f) { f = 0; }, "resolution fraction must be in (0, 1], got 0");
  expect_error([](B&, W&, double& f) { f = 1.5; }, "resolution fraction must be in (0, 1], got 1.5");
  // Bounds given only in part are rejected too: here y, v and omega are all 0, 0.
  EXPECT_THROW(UnicycleSpace({.x_min = 0, .x_max = 1}), ParameterError);
}

TEST(UnicycleSpace, IsAMetricOnRandomStates) {
  const UnicycleSpace s(box(), {.theta = 0.5, .v = 2.0, .omega = 3.0});
  Rng rng(23);
  const auto draw = [&] {
    State x;
    s.sample_uniform(rng, x);
    x[U::kTheta] += 2 * kPi * static_cast<double>(rng.uniform_index(5)) - 4 * kPi;  // any turn count
    return x;
  };
  for (int i = 0; i < 5000; ++i) {
    const State a = draw(), b = draw(), c = draw();
    const double ab = s.distance(a, b), bc = s.distance(b, c), ac = s.distance(a, c);
    ASSERT_EQ(s.distance(a, a), 0.0);
    ASSERT_GE(ab, 0.0);
    ASSERT_EQ(ab, s.distance(b, a));  // exactly symmetric
    ASSERT_LE(ac, ab + bc + 1e-12);
    ASSERT_LE(ab, s.maximum_extent() + 1e-12);
  }
}

TEST(UnicycleSpace, ExtentIsTheFarthestPairAndSetsTheResolution) {
  const UnicycleSpace s({.x_min = 0, .x_max = 3, .y_min = 0, .y_max = 4, .v_min = 0, .v_max = 1, .omega_min = -1,
                         .omega_max = 1},
                        {}, 0.05);
  // sqrt(3^2 + 4^2 + pi^2 + 1^2 + 2^2) = sqrt(30 + pi^2), reached by opposite corners, antipodal headings.
  const double extent = std::sqrt(30.0 + kPi * kPi);
  EXPECT_NEAR(s.maximum_extent(), extent, 1e-12);
  EXPECT_NEAR(s.distance(U::make_state(0, 0, 0, 0, -1), U::make_state(3, 4, kPi, 1, 1)), extent, 1e-12);
  EXPECT_NEAR(s.resolution(), 0.05 * extent, 1e-12);
}

TEST(UnicycleSpace, EnforceBoundsClampsAndWrapsAndInBoundsChecksTheBox) {
  const UnicycleSpace s(box());
  State x = U::make_state(11, -1, 4.0, 3, -2);
  EXPECT_FALSE(s.in_bounds(x));
  s.enforce_bounds(x);
  EXPECT_EQ(x[U::kX], 10.0);
  EXPECT_EQ(x[U::kY], 0.0);
  EXPECT_NEAR(x[U::kTheta], 4.0 - 2 * kPi, 1e-12);
  EXPECT_EQ(x[U::kV], 2.0);
  EXPECT_EQ(x[U::kOmega], -1.0);
  EXPECT_TRUE(s.in_bounds(x));
  x = U::make_state(1, 1, -kPi, 0, 0);
  s.enforce_bounds(x);
  EXPECT_EQ(x[U::kTheta], kPi);  // the seam's representative is pi
  EXPECT_TRUE(s.in_bounds(U::make_state(1, 1, 100.0, 0, 0)));  // any finite heading names an angle
  EXPECT_FALSE(s.in_bounds(U::make_state(1, 1, 0, 2.1, 0)));
  EXPECT_FALSE(s.in_bounds(U::make_state(1, 1, 0, 0, 1.1)));
  EXPECT_FALSE(s.in_bounds(U::make_state(1, 1, std::nan(""), 0, 0)));
  EXPECT_FALSE(s.in_bounds(State::Zero(4)));
}

TEST(UnicycleSpace, HeadingHelpersWrapIntoMinusPiExclusivePiInclusive) {
  EXPECT_EQ(U::wrap_heading(kPi), kPi);
  EXPECT_EQ(U::wrap_heading(-kPi), kPi);
  EXPECT_EQ(U::wrap_heading(1.25), 1.25);  // in range: unchanged, bit for bit
  EXPECT_NEAR(U::wrap_heading(3 * kPi + 0.25), -kPi + 0.25, 1e-12);
  EXPECT_NEAR(U::wrap_heading(-7.0), -7.0 + 2 * kPi, 1e-12);
  EXPECT_TRUE(std::isnan(U::wrap_heading(std::nan(""))));
  EXPECT_NEAR(U::heading_difference(3.1, -3.1), 2 * kPi - 6.2, 1e-12);
  EXPECT_NEAR(U::heading_difference(-3.1, 3.1), -(2 * kPi - 6.2), 1e-12);
  EXPECT_EQ(U::heading_difference(0.0, kPi), kPi);  // antipodal: counter-clockwise
}

TEST(UnicycleSpace, EmbeddingDistanceIsALowerBoundOfTheMetric) {
  const UnicycleSpace s(box(), {.theta = 2.0, .v = 0.5, .omega = 3.0});
  Rng rng(3);
  for (int i = 0; i < 2000; ++i) {
    State x, y;
    s.sample_uniform(rng, x);
    s.sample_uniform(rng, y);
    double ex[6], ey[6], sq = 0;
    s.embed(x, ex);
    s.embed(y, ey);
    for (int j = 0; j < 6; ++j) sq += (ex[j] - ey[j]) * (ex[j] - ey[j]);
    ASSERT_LE(std::sqrt(sq), s.distance(x, y) + 1e-12);
  }
}

}  // namespace
}  // namespace amp::core
