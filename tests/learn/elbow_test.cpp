#include "amp/learn/elbow.hpp"

#include <vector>

#include <gtest/gtest.h>

namespace amp::learn {
namespace {

using Curve = std::vector<double>;

TEST(Elbow, PicksTheLargestSecondDifference) {
  // d2(c) = f(c-1) - 2 f(c) + f(c+1): c=2: 0, c=3: 0, c=4: 0.5 - 0.5 + 0.2 = 0.2, c=5: 0.25 - 0.4 + 0.15 = 0.
  EXPECT_EQ(elbow_choice(Curve{1.0, 0.75, 0.5, 0.25, 0.2, 0.15}), 4);
}

TEST(Elbow, TiesGoToTheSmallerC) {
  // d2(2) = 1 - 1 + 0.25 = 0.25, d2(3) = 0.5 - 0.5 + 0.25 = 0.25 (exact in binary), d2(4) = 0.
  EXPECT_EQ(elbow_choice(Curve{1.0, 0.5, 0.25, 0.25, 0.25}), 2);
}

TEST(Elbow, EndsAreNeverChosenAndNoCurvatureMeansOneCluster) {
  // The drop is steepest into c = C = 4, but C has no right neighbour: no positive d2 -> 1.
  EXPECT_EQ(elbow_choice(Curve{1.0, 0.75, 0.5, 0.0}), 1);
  // A straight line and a constant (all points equal: T = 0) have no elbow either.
  EXPECT_EQ(elbow_choice(Curve{1.0, 0.75, 0.5, 0.25, 0.0}), 1);
  EXPECT_EQ(elbow_choice(Curve{0.0, 0.0, 0.0, 0.0}), 1);
  // Fewer than three values: no interior point.
  EXPECT_EQ(elbow_choice(Curve{1.0, 0.1}), 1);
  EXPECT_EQ(elbow_choice(Curve{1.0}), 1);
  EXPECT_EQ(elbow_choice(Curve{}), 1);
}

TEST(Elbow, SumsOfSquares) {
  Eigen::MatrixXd x(4, 2);
  x << 0, 0,  //
      2, 0,   //
      10, 1,  //
      10, 3;
  // Grand mean (5.5, 1): 30.25 + 1 + 12.25 + 1 + 20.25 + 0 + 20.25 + 4 = 89.
  EXPECT_DOUBLE_EQ(total_sum_of_squares(x), 89.0);
  Eigen::MatrixXd centres(2, 2);
  centres << 1, 0,  //
      10, 2;
  EXPECT_DOUBLE_EQ(within_sum_of_squares(x, {0, 0, 1, 1}, centres), 4.0);
}

}  // namespace
}  // namespace amp::learn
