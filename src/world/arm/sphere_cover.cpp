// Sphere covers of an arm's links (docs/arms.md, "Sphere model"). Each link's solids are cut into
// small convex pieces (sphere_pieces.hpp); a sphere covers a piece when it holds the piece's corners.
// cover_with_spheres groups the pieces by k-means and encloses each group; inflate_to_cover grows
// given spheres until every piece is held. Either way the result is a cover by construction.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <Eigen/Eigenvalues>

#include "amp/core/error.hpp"
#include "amp/world/arm_spheres.hpp"
#include "sphere_pieces.hpp"

namespace amp::world {

namespace {

using detail::LinkPieces;

// Rounding absorbed by every radius: a corner computed as exactly on a sphere stays inside it.
constexpr double kRelativeMargin = 1e-9;
constexpr double kAbsoluteMargin = 1e-9;  // metres
constexpr int kLloydIterations = 10;
// Badoiu-Clarkson steps refining a group's centre from its bounding-box centre (the best is kept).
constexpr int kCentreSteps = 16;
// How much distances across a link count, against along it, when its pieces are grouped
// (squeezed_across). Changing the generator means raising kGeneratorVersion in sphere_cache.cpp.
constexpr double kAcrossWeight = 0.3;

double padded(double radius) { return radius * (1.0 + kRelativeMargin) + kAbsoluteMargin; }

void validate(const SphereCoverOptions& o) {
  if (!(o.piece_size > 0.0) || !std::isfinite(o.piece_size)) {
    throw ParameterError("sphere cover: piece_size must be positive, got " + std::to_string(o.piece_size));
  }
  if (o.max_per_link < 1) throw ParameterError("sphere cover: max_per_link must be at least 1, got " + std::to_string(o.max_per_link));
  if (!(o.bulge >= 0.0) || !std::isfinite(o.bulge)) {
    throw ParameterError("sphere cover: bulge must be a non-negative number, got " + std::to_string(o.bulge));
  }
}

template <class Points>
std::pair<int, double> farthest(const Points& points, const Eigen::Vector3d& c) {
  int best = 0;
  double d2 = -1.0;
  for (int i = 0; i < static_cast<int>(points.size()); ++i) {
    const double e = (points[static_cast<std::size_t>(i)] - c).squaredNorm();
    if (e > d2) best = i, d2 = e;  // strict: the lowest index wins ties
  }
  return {best, std::sqrt(d2)};
}

std::vector<Eigen::Vector3d> centroids(const LinkPieces& p) {
  std::vector<Eigen::Vector3d> out;
  out.reserve(static_cast<std::size_t>(p.count()));
  for (int i = 0; i < p.count(); ++i) {
    Eigen::Vector3d s = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& c : p.piece(i)) s += c;
    out.push_back(s / static_cast<double>(p.piece(i).size()));
  }
  return out;
}

// Farthest-point seeding, starting from the point farthest from the mean.
std::vector<Eigen::Vector3d> seeds(const std::vector<Eigen::Vector3d>& pts, int k) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : pts) mean += p;
  mean /= static_cast<double>(pts.size());
  std::vector<Eigen::Vector3d> out{pts[static_cast<std::size_t>(farthest(pts, mean).first)]};
  std::vector<double> gap(pts.size(), std::numeric_limits<double>::infinity());
  while (static_cast<int>(out.size()) < k) {
    int best = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      gap[i] = std::min(gap[i], (pts[i] - out.back()).squaredNorm());
      if (gap[i] > gap[static_cast<std::size_t>(best)]) best = static_cast<int>(i);
    }
    out.push_back(pts[static_cast<std::size_t>(best)]);
  }
  return out;
}

int nearest(const std::vector<Eigen::Vector3d>& centres, const Eigen::Vector3d& p) {
  int best = 0;
  double d2 = std::numeric_limits<double>::infinity();
  for (int j = 0; j < static_cast<int>(centres.size()); ++j) {
    const double e = (centres[static_cast<std::size_t>(j)] - p).squaredNorm();
    if (e < d2) best = j, d2 = e;
  }
  return best;
}

// Lloyd's iterations on the piece centroids; returns each piece's group.
std::vector<int> k_means(const std::vector<Eigen::Vector3d>& pts, int k) {
  std::vector<Eigen::Vector3d> centres = seeds(pts, k);
  std::vector<int> group(pts.size(), 0);
  for (int it = 0; it < kLloydIterations; ++it) {
    for (std::size_t i = 0; i < pts.size(); ++i) group[i] = nearest(centres, pts[i]);
    std::vector<Eigen::Vector3d> sum(centres.size(), Eigen::Vector3d::Zero());
    std::vector<int> n(centres.size(), 0);
    for (std::size_t i = 0; i < pts.size(); ++i) {
      sum[static_cast<std::size_t>(group[i])] += pts[i];
      ++n[static_cast<std::size_t>(group[i])];
    }
    // An emptied group keeps its centre; it is dropped at the end if still empty.
    for (std::size_t j = 0; j < centres.size(); ++j) {
      if (n[j] > 0) centres[j] = sum[j] / n[j];
    }
  }
  return group;
}

// The smallest sphere found around `corners`: the bounding-box centre, then Badoiu-Clarkson steps
// toward the farthest corner (Badoiu and Clarkson, "Smaller core-sets for balls", SODA 2003); the
// radius is the exact farthest distance from the best centre seen, so every corner is inside.
LinkSphere enclose(const std::vector<Eigen::Vector3d>& corners, int link) {
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& c : corners) box.extend(c);
  Eigen::Vector3d c = box.center();
  auto [far, r] = farthest(corners, c);
  LinkSphere best{link, c, r};
  for (int i = 1; i <= kCentreSteps; ++i) {
    // c += (p - c) / (i + 1) in the paper; begun at a good centre, the steps start small, as if
    // kCentreSteps steps had been taken already.
    c += (corners[static_cast<std::size_t>(far)] - c) / static_cast<double>(i + kCentreSteps);
    std::tie(far, r) = farthest(corners, c);
    if (r < best.radius) best.center = c, best.radius = r;
  }
  best.radius = padded(best.radius);
  return best;
}


// The link's long axis (principal axis of its piece centroids) and the frame that squeezes
// distances across it. Pieces grouped by plain k-means become patches of the surface, and a patch's
// ball bulges out of the solid by nearly its radius; grouped with distances across the axis shrunk,
// they become slabs across the link, whose balls are centred inside it and bulge out little.
struct LinkAxis {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  Eigen::Vector3d along = Eigen::Vector3d::UnitZ();
  Eigen::Matrix3d squeeze = Eigen::Matrix3d::Identity();
};

LinkAxis link_axis(const std::vector<Eigen::Vector3d>& pts) {
  LinkAxis a;
  for (const Eigen::Vector3d& q : pts) a.mean += q;
  a.mean /= static_cast<double>(pts.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& q : pts) cov += (q - a.mean) * (q - a.mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> pca(cov);  // eigenvalues ascending
  a.along = pca.eigenvectors().col(2);
  a.squeeze = pca.eigenvectors().transpose();
  a.squeeze.row(0) *= kAcrossWeight;
  a.squeeze.row(1) *= kAcrossWeight;
  return a;
}

// A slab's ball is as tight as it gets when its radius is close to the farthest its corners lie
// from the axis line through its centre: what is left beyond that is the ball's reach along the
// axis, which more slabs shrink.
bool tight(const LinkSphere& s, const std::vector<Eigen::Vector3d>& corners, const Eigen::Vector3d& along, double bulge) {
  double across = 0.0;
  for (const Eigen::Vector3d& c : corners) {
    const Eigen::Vector3d d = c - s.center;
    across = std::max(across, (d - d.dot(along) * along).norm());
  }
  return s.radius <= (1.0 + bulge) * across;
}

// One sphere per group of pieces, for k = 1, 2, ... groups until every sphere is tight.
std::vector<LinkSphere> cover_pieces(const LinkPieces& p, const SphereCoverOptions& o, int link) {
  if (p.count() == 0) return {};
  std::vector<Eigen::Vector3d> pts = centroids(p);
  const LinkAxis axis = link_axis(pts);
  for (Eigen::Vector3d& q : pts) q = axis.squeeze * (q - axis.mean);
  const int most = std::min(o.max_per_link, p.count());
  std::vector<LinkSphere> out;
  for (int k = 1; k <= most; ++k) {
    const std::vector<int> group = k_means(pts, k);
    std::vector<std::vector<Eigen::Vector3d>> corners(static_cast<std::size_t>(k));
    for (int i = 0; i < p.count(); ++i) {
      auto& g = corners[static_cast<std::size_t>(group[static_cast<std::size_t>(i)])];
      g.insert(g.end(), p.piece(i).begin(), p.piece(i).end());
    }
    out.clear();
    bool all_tight = true;
    for (const auto& g : corners) {
      if (g.empty()) continue;
      out.push_back(enclose(g, link));
      all_tight = all_tight && tight(out.back(), g, axis.along, o.bulge);
    }
    if (all_tight) break;
  }
  return out;
}

// Every point of a sphere lies within its radius of its centre, and the centre lies within d of a
// solid point (a piece corner, or a ball): r + d bounds the excess. A sphere inside a ball adds none.
double excess(const LinkSphere& s, const LinkPieces& p) {
  double d = std::numeric_limits<double>::infinity();
  for (const detail::Ball& b : p.balls) {
    const double gap = (s.center - b.center).norm();
    if (gap + s.radius <= b.radius) return 0.0;
    d = std::min(d, std::max(0.0, gap - b.radius));
  }
  for (const Eigen::Vector3d& c : p.corners) d = std::min(d, (c - s.center).norm());
  return s.radius + d;
}

LinkCoverReport report(const LinkPieces& p, std::span<const LinkSphere> spheres, int link, double inflation) {
  LinkCoverReport r;
  r.link = link;
  r.spheres = static_cast<int>(spheres.size());
  for (const LinkSphere& s : spheres) {
    r.excess_bound = std::max(r.excess_bound, excess(s, p));
    r.sphere_volume += 4.0 / 3.0 * std::numbers::pi * s.radius * s.radius * s.radius;
  }
  r.box_volume = p.box.volume();
  r.inflation = inflation;
  return r;
}

// The radius `s` needs to hold the piece.
double needed(const LinkSphere& s, std::span<const Eigen::Vector3d> piece) {
  double need = 0.0;
  for (const Eigen::Vector3d& c : piece) need = std::max(need, (c - s.center).norm());
  return padded(need);
}

double needed(const LinkSphere& s, const detail::Ball& b) { return padded((b.center - s.center).norm() + b.radius); }

// Each piece (and ball) goes to the sphere that must grow least from its given radius (`given`), which
// then grows to hold it. Measuring from the given radii, not the grown ones, keeps a sphere from
// creeping along a surface piece by piece: no sphere grows more than the worst piece requires.
template <class Piece>
void absorb(std::span<LinkSphere> spheres, std::span<const double> given, const Piece& piece) {
  std::size_t best = 0;
  double least = std::numeric_limits<double>::infinity(), need = 0.0;
  for (std::size_t j = 0; j < spheres.size(); ++j) {
    const double n = needed(spheres[j], piece);
    if (n - given[j] < least) best = j, least = n - given[j], need = n;  // strict: lowest index wins ties
  }
  spheres[best].radius = std::max(spheres[best].radius, need);
}

void check_given(const ArmModel& model, const std::vector<LinkSphere>& given, const std::string& label) {
  for (const LinkSphere& s : given) {
    if (s.link < 0 || s.link >= static_cast<int>(model.links().size())) {
      throw ParameterError(label + ": sphere of link index " + std::to_string(s.link) + ", not a link of '" + model.name() + "'");
    }
    if (!s.center.allFinite() || !std::isfinite(s.radius) || s.radius < 0.0) {
      throw ParameterError(label + ": sphere of link '" + model.link(s.link).name + "' has a non-finite centre or a bad radius");
    }
  }
}

}  // namespace

SphereCover cover_with_spheres(const ArmModel& model, const SphereCoverOptions& options) {
  validate(options);
  SphereCover out;
  out.options = options;
  for (int l = 0; l < static_cast<int>(model.links().size()); ++l) {
    const LinkPieces p = detail::cut_into_pieces(model.link(l).collision, options.piece_size);
    if (p.empty()) continue;
    std::vector<LinkSphere> spheres = cover_pieces(p, options, l);
    for (const detail::Ball& b : p.balls) spheres.push_back({l, b.center, b.radius});  // exact
    out.links.push_back(report(p, spheres, l, 0.0));
    out.spheres.insert(out.spheres.end(), spheres.begin(), spheres.end());
  }
  return out;
}

SphereCover inflate_to_cover(const ArmModel& model, std::vector<LinkSphere> given, const std::string& label,
                             const SphereCoverOptions& options) {
  validate(options);
  check_given(model, given, label);
  std::stable_sort(given.begin(), given.end(), [](const LinkSphere& a, const LinkSphere& b) { return a.link < b.link; });
  SphereCover out;
  out.options = options;
  out.spheres = std::move(given);
  auto begin = out.spheres.begin();
  for (int l = 0; l < static_cast<int>(model.links().size()); ++l) {
    const auto end = std::find_if(begin, out.spheres.end(), [l](const LinkSphere& s) { return s.link != l; });
    const std::span<LinkSphere> mine(begin, end);
    begin = end;
    const LinkPieces p = detail::cut_into_pieces(model.link(l).collision, options.piece_size);
    if (p.empty()) continue;  // spheres of a link without solids stay as given
    if (mine.empty()) throw ParameterError("link '" + model.link(l).name + "' has collision geometry but no sphere in " + label);
    std::vector<double> before;
    for (const LinkSphere& s : mine) before.push_back(s.radius);
    for (int i = 0; i < p.count(); ++i) absorb(mine, before, p.piece(i));
    for (const detail::Ball& b : p.balls) absorb(mine, before, b);
    double inflation = 0.0;
    for (std::size_t j = 0; j < mine.size(); ++j) inflation = std::max(inflation, mine[j].radius - before[j]);
    out.links.push_back(report(p, mine, l, inflation));
  }
  return out;
}

}  // namespace amp::world
