#pragma once
#include <vector>

namespace amp::core {

// What one leading coordinate of a state is.
enum class CoordinateKind {
  kLinear,  // a line clamped to [lo, hi]: a translation, a slide or an angle with limits (never wraps)
  kAngle,   // an angle that wraps around, compared the short way round; lo and hi are not bounds
};

struct CoordinateAxis {
  CoordinateKind kind = CoordinateKind::kLinear;
  double lo = 0.0;
  double hi = 0.0;
  double weight = 1.0;  // metric weight: length per unit of this coordinate
};

// A space's states coordinate by coordinate, for code that bounds or steps coordinates one at a
// time rather than through distance() and interpolate() (the KD-tree's per-block bound, the grid
// chart of the competence planners): `axes`, one per leading coordinate, then, when `quaternion`,
// a unit quaternion (qx, qy, qz, qw) ending the state. The metric it implies:
//   distance = sqrt(sum_i (weight_i d_i)^2) + rotation_weight * angle(q_a, q_b),
// d_i the difference of coordinate i (the short way round for an angle), angle the rotation angle
// between the two orientations in [0, pi] (q and -q being the same rotation).
struct CoordinateLayout {
  std::vector<CoordinateAxis> axes;
  bool quaternion = false;
  double rotation_weight = 0.0;  // of the quaternion's angle

  // SE3's layout: three linear coordinates of one weight w (a position) then a quaternion, so that
  // distance = w |p_a - p_b| + rotation_weight * angle.
  bool rigid_body_3d() const {
    if (!quaternion || axes.size() != 3) return false;
    for (const CoordinateAxis& a : axes) {
      if (a.kind != CoordinateKind::kLinear || a.weight != axes.front().weight) return false;
    }
    return true;
  }
};

}  // namespace amp::core
