#pragma once
#include <Eigen/Core>

namespace amp {

// Largest number of coordinates a state can hold (SE3 uses 7, the SCARA arm 5, linkages up to 12).
inline constexpr int kMaxDof = 12;

// A configuration: coordinates stored inline (no heap traffic), so copies are cheap and safe.
using State = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxDof, 1>;

}  // namespace amp
