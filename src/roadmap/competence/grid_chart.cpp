#include "amp/roadmap/competence/grid_chart.hpp"

#include <numbers>
#include <optional>
#include <string>

#include "amp/core/error.hpp"
#include "amp/core/joint_space.hpp"  // angle_difference, wrap_angle
#include "amp/core/se3_space.hpp"    // Se3Space::rotation: a state's quaternion

namespace amp::roadmap {

namespace {
constexpr double kTwoPi = 2.0 * std::numbers::pi;
}

GridChart::GridChart(const core::Space& space, int steps) {
  if (steps < 1) throw ParameterError("grid: steps per degree of freedom must be >= 1, got " + std::to_string(steps));
  const std::optional<core::CoordinateLayout> layout = space.coordinate_layout();
  // The chart knows lines and angles, and a quaternion only after a 3-D position (SE3).
  if (!layout || (layout->quaternion && !layout->rigid_body_3d())) {
    throw ParameterError("grid: no grid chart for a '" + std::string(space.kind()) + "' space");
  }
  const double n = steps;
  for (const core::CoordinateAxis& a : layout->axes) {
    const bool wraps = a.kind == core::CoordinateKind::kAngle;
    axis_.push_back(layout->quaternion ? Axis::kTranslation : wraps ? Axis::kAngle : Axis::kLinear);
    step_.push_back(wraps ? kTwoPi / n : (a.hi - a.lo) / n);
    lo_.push_back(a.lo);
    hi_.push_back(a.hi);
  }
  if (!layout->quaternion) return;
  for (int i = 0; i < 3; ++i) {
    axis_.push_back(Axis::kRotation);
    step_.push_back(kTwoPi / n);
    lo_.push_back(0.0);
    hi_.push_back(0.0);
  }
}

void GridChart::set_origin(const State& origin) {
  origin_ = origin;
  if (axis_.size() == 6 && axis_[3] == Axis::kRotation) origin_rotation_ = core::Se3Space::rotation(origin);
}

void GridChart::coordinates(const State& s, double* x) const {
  if (axis_.back() == Axis::kRotation) {
    for (int i = 0; i < 3; ++i) x[i] = s[i] - origin_[i];
    const Eigen::AngleAxisd r(origin_rotation_.conjugate() * core::Se3Space::rotation(s));
    const Eigen::Vector3d v = r.angle() * r.axis();
    for (int i = 0; i < 3; ++i) x[3 + i] = v[i];
    return;
  }
  for (std::size_t i = 0; i < axis_.size(); ++i) {
    x[i] = axis_[i] == Axis::kAngle ? core::angle_difference(origin_[static_cast<Eigen::Index>(i)], s[static_cast<Eigen::Index>(i)])
                                    : s[static_cast<Eigen::Index>(i)] - origin_[static_cast<Eigen::Index>(i)];
  }
}

bool GridChart::state_at(const double* x, State& out) const {
  if (axis_.back() == Axis::kRotation) {
    out.resize(7);
    for (int i = 0; i < 3; ++i) {
      out[i] = origin_[i] + x[i];
      if (out[i] < lo_[static_cast<std::size_t>(i)] || out[i] > hi_[static_cast<std::size_t>(i)]) return false;
    }
    const Eigen::Vector3d v(x[3], x[4], x[5]);
    const double angle = v.norm();
    const Eigen::Quaterniond d =
        angle > 0.0 ? Eigen::Quaterniond(Eigen::AngleAxisd(angle, v / angle)) : Eigen::Quaterniond::Identity();
    const Eigen::Quaterniond q = (origin_rotation_ * d).normalized();
    out[3] = q.x();
    out[4] = q.y();
    out[5] = q.z();
    out[6] = q.w();
    return true;
  }
  out.resize(static_cast<Eigen::Index>(axis_.size()));
  for (std::size_t i = 0; i < axis_.size(); ++i) {
    const auto e = static_cast<Eigen::Index>(i);
    out[e] = origin_[e] + x[i];
    if (axis_[i] == Axis::kAngle) {
      out[e] = core::wrap_angle(out[e]);
    } else if (out[e] < lo_[i] || out[e] > hi_[i]) {
      return false;
    }
  }
  return true;
}

}  // namespace amp::roadmap
