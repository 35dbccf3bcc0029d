#include "amp/learn/standardize.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace amp::learn {
namespace {

TEST(Standardize, ZScoresWithSampleDeviation) {
  Eigen::MatrixXd x(4, 3);
  x << 1, 10, 5,  //
      2, 10, 5,   //
      3, 10, 5,   //
      6, 10, 5;
  const Eigen::MatrixXd z = standardize(x);
  // Column 0: mean 3, squares 4+1+0+9 = 14, sd = sqrt(14/3).
  const double sd = std::sqrt(14.0 / 3.0);
  EXPECT_NEAR(z(0, 0), -2.0 / sd, 1e-15);
  EXPECT_NEAR(z(3, 0), 3.0 / sd, 1e-15);
  EXPECT_NEAR(z.col(0).mean(), 0.0, 1e-15);
  EXPECT_NEAR(z.col(0).squaredNorm() / 3.0, 1.0, 1e-14);
  // Constant columns stay at zero rather than dividing by zero.
  EXPECT_TRUE(z.col(1).isZero(0.0));
  EXPECT_TRUE(z.col(2).isZero(0.0));
}

TEST(Standardize, ConstantUpToRoundingAndSingleRow) {
  Eigen::MatrixXd x(3, 1);
  x << 0.1 + 0.2, 0.3, 0.3;  // differs in the last bit only
  EXPECT_TRUE(standardize(x).isZero(0.0));
  EXPECT_TRUE(standardize(Eigen::MatrixXd::Constant(1, 2, 7.0)).isZero(0.0));
}

}  // namespace
}  // namespace amp::learn
