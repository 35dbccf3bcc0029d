#pragma once
#include <span>
#include <vector>

#include <Eigen/Core>

namespace amp::learn {

// The elbow criterion of UAS (the UAS region-identification study, section 2.1.4).
//
// The curve: f(c) = W(c) / T for c = 1..C, where W(c) = sum over the c clusters of the squared
// distances of their points to their centre (the within-cluster variances, each times n) and T =
// the total sum of squares about the grand mean (the data variance times n); so f(1) = 1 and f
// falls towards 0. (1 - f is the "variance explained".)
//
// The choice: the second difference d2(c) = f(c-1) - 2 f(c) + f(c+1) exists for 2 <= c <= C-1 only,
// and the chosen c maximises it; ties go to the smaller c. Consequences, by construction:
//  - c = 1 and c = C are never chosen by an elbow (neither has two neighbours), so a single blob
//    still gets 2 <= c <= C-1 clusters;
//  - if no d2(c) is positive (C < 3, a straight or concave curve, all points equal: T = 0 and the
//    curve is taken as all zeros), there is no elbow and the choice is c = 1.
int elbow_choice(std::span<const double> curve);

// Sum of squared distances of the points (rows) to their mean.
double total_sum_of_squares(const Eigen::MatrixXd& points);

// Sum of squared distances of each point to the centre of its cluster.
double within_sum_of_squares(const Eigen::MatrixXd& points, const std::vector<int>& labels,
                             const Eigen::MatrixXd& centres);

}  // namespace amp::learn
