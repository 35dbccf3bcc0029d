// The calibrated scale (nav::kCalibratedScale, the default of `amp sins` and of the SINS methods)
// is what the calibration finds with its default settings: rerunning `amp sins --calibrate` gives
// the same factor and step limit, and the paper's baselines inside the check's intervals. About
// 5 minutes: label `slow` (`make slow`), outside the default suite.
#include <gtest/gtest.h>

#include "amp/bench/sins_calibration.hpp"

namespace amp::bench {
namespace {

TEST(SinsScaleReproduction, DefaultScaleIsTheCalibrationsResult) {
  const SinsCalibration r = calibrate_sins_scale(SinsCalibrationSettings{});
  ASSERT_TRUE(r.reached) << r.why;
  EXPECT_DOUBLE_EQ(r.scale.factor, nav::kCalibratedScale.factor);
  EXPECT_EQ(r.scale.step_limit, nav::kCalibratedScale.step_limit);
  EXPECT_TRUE(r.static_share.holds(0.145));
  EXPECT_TRUE(r.random_share.holds(0.415));
}

}  // namespace
}  // namespace amp::bench
