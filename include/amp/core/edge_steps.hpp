#pragma once
#include <cmath>
#include <cstdint>

namespace amp::core {

// The most segments one edge may be cut into. Up to 2^53 every step index i and the count n are
// exact doubles, so t = i / n is exact enough and consecutive steps stay distinct; beyond it the
// count itself is not representable. (Problem files are held to far fewer: kMinResolutionFraction.)
inline constexpr std::int64_t kMaxEdgeSegments = std::int64_t{1} << 53;

// The number of segments ceil(distance / resolution), at least 1, with which an edge of that length
// is checked at that resolution; 0 when it cannot be represented (NaN, infinite, or more than
// kMaxEdgeSegments), which callers treat as an edge they refuse. Never wraps.
inline std::int64_t edge_segments(double distance, double resolution) noexcept {
  const double n = std::ceil(distance / resolution);
  if (!(n <= static_cast<double>(kMaxEdgeSegments))) return 0;  // also NaN
  return n < 1.0 ? 1 : static_cast<std::int64_t>(n);
}

// The finest `resolution` a problem file may give (a fraction of the space's extent): an edge across
// the space then takes 10^9 CD calls, minutes of work, so anything finer is a mistake (an absolute
// step written as a fraction). Loaders refuse it; spaces built in code may go down to kMaxEdgeSegments.
inline constexpr double kMinResolutionFraction = 1e-9;

}  // namespace amp::core
