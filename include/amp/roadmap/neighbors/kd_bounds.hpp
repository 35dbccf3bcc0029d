#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "amp/core/coordinate_layout.hpp"
#include "amp/core/space.hpp"

namespace amp::roadmap {

// Lower bounds of Space::distance used by DynamicKdTree to prune: from a query to any state whose
// stored coordinates lie in an axis-aligned box, and to one stored point. A bound policy provides
//   int dimension() const;                        stored coordinates per state
//   void store(const State&, double* out);        the coordinates the tree splits on
//   double split_scale(int d) const;              distance per unit of coordinate d (split choice)
//   void prepare(const State& q);                 per-query set-up
//   double box(const float* lo, const float* hi, double r) const;
//   double point(const float* x, double r) const;
//   double float_slack(double m) const;           how much rounding coordinates (|x| <= m) to
//                                                 float can lower point()
// (+infinity, or any value above r, when the bound exceeds r: a cheap early out)
//   double slack() const;                         absolute rounding allowance of the bounds
// Both bounds may exceed the true distance only by rounding, which the tree's slack absorbs.

// Squared distance from x to the interval [lo, hi]; max() rather than branches, which a search
// would mispredict (the side of x is random).
inline constexpr double kFloatEps = 0x1.0p-24;  // relative rounding of double to float

inline double gap_squared(double x, float lo, float hi) {
  const double g = std::max(std::max(lo - x, x - hi), 0.0);
  return g * g;
}

// Any space, through its embedding: the Euclidean distance between embedded points is a lower
// bound of distance() (Space's contract), over every embedding variant of the query.
class EmbeddingBound {
 public:
  explicit EmbeddingBound(const core::Space& space)
      : space_(&space),
        dim_(space.embedding_dimension()),
        variants_(space.embedding_variants()),
        query_(static_cast<std::size_t>(dim_ * variants_)) {}

  int dimension() const { return dim_; }
  void store(const State& s, double* out) const { space_->embed(s, out); }
  double split_scale(int /*d*/) const { return 1.0; }
  void prepare(const State& q) {
    for (int v = 0; v < variants_; ++v) space_->embed_variant(q, v, query_.data() + v * dim_);
  }
  double box(const float* lo, const float* hi, double /*r*/) const {
    double best = std::numeric_limits<double>::infinity();
    for (int v = 0; v < variants_; ++v) {
      const double* q = query_.data() + v * dim_;
      double sq = 0.0;
      for (int d = 0; d < dim_; ++d) sq += gap_squared(q[d], lo[d], hi[d]);
      best = std::min(best, sq);
    }
    return std::sqrt(best);
  }
  double point(const float* x, double /*r*/) const {
    double best = std::numeric_limits<double>::infinity();
    for (int v = 0; v < variants_; ++v) {
      const double* q = query_.data() + v * dim_;
      double sq = 0.0;
      for (int d = 0; d < dim_; ++d) sq += (q[d] - x[d]) * (q[d] - x[d]);
      best = std::min(best, sq);
    }
    return std::sqrt(best);
  }
  double slack() const { return 0.0; }
  // |x - float(x)| <= 2^-24 |x| per coordinate.
  double float_slack(double m) const { return 2.0 * std::sqrt(static_cast<double>(dim_)) * m * kFloatEps; }

 private:
  const core::Space* space_;
  int dim_;
  int variants_;
  std::vector<double> query_;  // one embedded query per variant
};

// SE3, block by block: distance = w_t |dp| + w_r * angle is bounded below by the Euclidean
// distance over the translation block plus w_r times the angle implied by the smallest chord over
// the quaternion block, rather than by one Euclidean distance over all 7 coordinates (which is
// loose by up to sqrt(2) and makes a 7-D ball search). Quaternions are stored in the hemisphere
// w >= 0 and the query is tried with both signs, since q and -q are the same rotation.
class Se3Bound {
 public:
  // For a layout with layout.rigid_body_3d() (Se3Space's). Weights shaved by a relative 1e-12 so
  // that rounding keeps the bound below the true distance.
  explicit Se3Bound(const core::CoordinateLayout& layout)
      : wt_(layout.axes.front().weight * kShave), wr_(layout.rotation_weight * kShave) {}

  int dimension() const { return 7; }
  void store(const State& s, double* out) {
    for (int i = 0; i < 3; ++i) out[i] = wt_ * s[i];
    const double sign = s[6] < 0.0 ? -1.0 : 1.0;  // canonical hemisphere w >= 0
    for (int i = 3; i < 7; ++i) out[i] = sign * s[i];
    note_norm(s);
  }
  // A unit of quaternion coordinate is worth about 2 w_r (chord c ~ angle / 2).
  double split_scale(int d) const { return d < 3 ? 1.0 : 2.0 * wr_; }
  void prepare(const State& q) {
    for (int i = 0; i < 3; ++i) q_[i] = wt_ * q[i];
    for (int i = 3; i < 7; ++i) q_[i] = q[i];
    note_norm(q);
  }
  double box(const float* lo, const float* hi, double r) const {
    double t = 0.0;
    for (int i = 0; i < 3; ++i) t += gap_squared(q_[i], lo[i], hi[i]);
    if (t > r * r) return kFar;
    double plus = 0.0, minus = 0.0;
    for (int i = 3; i < 7; ++i) {
      plus += gap_squared(q_[i], lo[i], hi[i]);
      minus += gap_squared(-q_[i], lo[i], hi[i]);
    }
    return combine(t, std::min(plus, minus), r);
  }
  double point(const float* x, double r) const {
    double t = 0.0;
    for (int i = 0; i < 3; ++i) t += (q_[i] - x[i]) * (q_[i] - x[i]);
    if (t > r * r) return kFar;
    double plus = 0.0, minus = 0.0;
    for (int i = 3; i < 7; ++i) {
      plus += (q_[i] - x[i]) * (q_[i] - x[i]);
      minus += (q_[i] + x[i]) * (q_[i] + x[i]);
    }
    return combine(t, std::min(plus, minus), r);
  }
  // Translation: as EmbeddingBound over 3 coordinates; rotation: unit quaternion coordinates move
  // the chord by at most 2 * 2^-24 and angle_from_chord' <= 3.75.
  double float_slack(double m) const {
    return 2.0 * (std::sqrt(3.0) * m + wr_ * 3.75 * 2.0) * kFloatEps;
  }
  // distance() takes acos of a dot product, which loses ~sqrt(eps) near angle 0 and more when a
  // quaternion is off unit length by delta (acos(1 - x) ~ sqrt(2x)): allow for both.
  double slack() const { return wr_ * (kAngleSlack + 4.0 * std::sqrt(max_norm_error_)); }

  // A lower bound of the rotation angle between unit quaternions at chord c (c = 2 sin(angle/4)):
  // 4 asin(c/2), truncated to its first three Taylor terms, all positive, so still a lower bound.
  static double angle_from_chord(double c) {
    const double x = std::min(0.5 * c, 1.0);
    const double x2 = x * x;
    return 4.0 * x * (1.0 + x2 * (1.0 / 6.0 + x2 * (3.0 / 40.0)));
  }

 private:
  static constexpr double kShave = 1.0 - 1e-12;
  static constexpr double kFar = std::numeric_limits<double>::infinity();

  // The bound from the squared translation gap t and squared chord c2; the two early outs skip
  // the square roots: a gap beyond r, or a chord beyond the one of angle r / w_r (c = 2 sin(a/4)
  // inverts the exact relation, so it is sound although angle_from_chord is truncated).
  double combine(double t, double c2, double r) const {
    if (r != cached_r_) {
      cached_r_ = r;
      const double a = r / wr_;
      const double c = 2.0 * std::sin(0.25 * a);
      cached_c2_ = a >= std::numbers::pi ? kFar : c * c * (1.0 + 1e-9);
    }
    if (c2 > cached_c2_) return kFar;
    return std::sqrt(t) + wr_ * angle_from_chord(std::sqrt(c2));
  }
  static constexpr double kAngleSlack = 1e-6;  // radians; far above acos's ~1e-8 near 1

  void note_norm(const State& s) {
    max_norm_error_ = std::max(max_norm_error_, std::abs(s.tail<4>().squaredNorm() - 1.0));
  }

  double wt_ = 1.0;
  double wr_ = 1.0;
  double q_[7] = {};
  double max_norm_error_ = 0.0;  // over every stored state and query so far
  mutable double cached_r_ = -1.0;  // the radius cached_c2_ was computed for
  mutable double cached_c2_ = 0.0;
};

}  // namespace amp::roadmap
