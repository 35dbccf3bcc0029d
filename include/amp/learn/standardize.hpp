#pragma once
#include <Eigen/Core>

namespace amp::learn {

// Per-column z-scores: (x - mean) / sd with the sample standard deviation (n - 1 divisor, as
// MATLAB's zscore, which the UAS paper used). A column whose sd is zero, or below 1e-12 of its
// magnitude (constant up to rounding), becomes all 0; with one row every column is 0.
Eigen::MatrixXd standardize(const Eigen::MatrixXd& points);

}  // namespace amp::learn
