#include "world/arm/arm_checker.hpp"

#include <cmath>
#include <limits>
#include <unordered_map>

#include "world/arm/arm_geometry.hpp"

namespace amp::world::detail {

namespace {

// GJK's distance between convex shapes is accurate to FCL's distance_tolerance (1e-6); a hull
// distance is trusted as a lower bound only after taking this off, and a hull closer than it is
// settled by the exact geometry.
constexpr double kHullSlack = 1e-5;

// One part of the robot as FCL sees it: its exact geometry and its convex hull, posed together.
struct PartObjects {
  std::unique_ptr<fcl::CollisionObjectd> exact, hull;
  bool has_hull() const { return hull->collisionGeometry() != exact->collisionGeometry(); }
};

bool collide(const fcl::CollisionObjectd* a, const fcl::CollisionObjectd* b) {
  fcl::CollisionRequestd request;
  fcl::CollisionResultd result;
  return fcl::collide(a, b, request, result) > 0;
}

double distance(const fcl::CollisionObjectd* a, const fcl::CollisionObjectd* b) {
  fcl::DistanceRequestd request;
  fcl::DistanceResultd result;
  fcl::distance(a, b, request, result);
  return result.min_distance;
}

// Hull first: a hull that does not touch settles it; one that does asks the exact geometry.
bool parts_collide(const PartObjects& a, const PartObjects& b) {
  if ((a.has_hull() || b.has_hull()) && !collide(a.hull.get(), b.hull.get())) return false;
  return collide(a.exact.get(), b.exact.get());
}

bool part_collides_with(const PartObjects& a, const fcl::CollisionObjectd* object) {
  if (a.has_hull() && !collide(a.hull.get(), object)) return false;
  return collide(a.exact.get(), object);
}

// A lower bound on the distance: the hulls' (less the slack), or the exact one where they touch.
double part_distance(const PartObjects& a, const fcl::CollisionObjectd* b_hull, const fcl::CollisionObjectd* b_exact,
                     bool b_has_hull) {
  if (a.has_hull() || b_has_hull) {
    const double d = distance(a.hull.get(), b_hull) - kHullSlack;
    if (d > 0.0) return d;
  }
  return distance(a.exact.get(), b_exact);
}

// The broad phase calls back with (hull, object) in either order; pairs the scene allows are skipped.
struct SceneQuery {
  const ArmEnvironment* env = nullptr;
  const std::unordered_map<const fcl::CollisionObjectd*, std::size_t>* scene_index = nullptr;
  const PartObjects* part = nullptr;
  int link = 0;
  bool hit = false;
  double distance = std::numeric_limits<double>::infinity();

  const fcl::CollisionObjectd* other(fcl::CollisionObjectd* a, fcl::CollisionObjectd* b) const {
    return a == part->hull.get() ? b : a;
  }
  bool skipped(const fcl::CollisionObjectd* object) const {
    return !scene_index->empty() && env->allowed(scene_index->at(object), link);
  }
};

bool collide_callback(fcl::CollisionObjectd* a, fcl::CollisionObjectd* b, void* raw) {
  auto* q = static_cast<SceneQuery*>(raw);
  const fcl::CollisionObjectd* object = q->other(a, b);
  if (!q->skipped(object)) q->hit = part_collides_with(*q->part, object);
  return q->hit;  // one contact decides
}

bool distance_callback(fcl::CollisionObjectd* a, fcl::CollisionObjectd* b, void* raw, double& dist) {
  auto* q = static_cast<SceneQuery*>(raw);
  const fcl::CollisionObjectd* object = q->other(a, b);
  if (!q->skipped(object)) q->distance = std::min(q->distance, part_distance(*q->part, object, object, false));
  dist = q->distance;
  return dist <= 0.0;
}

}  // namespace

struct ArmChecker::Scratch {
  std::vector<double> steps;  // one per group joint
  std::vector<PartObjects> parts;
  std::vector<Eigen::Isometry3d> poses;  // one per link
  std::unordered_map<const fcl::CollisionObjectd*, std::size_t> scene_index;  // only when the scene allows pairs
  SceneQuery query;
};

ArmChecker::ArmChecker(const ArmEnvironment& env, core::Counters& counters)
    : ValidityChecker(counters), env_(env), scratch_(std::make_unique<Scratch>()) {
  for (const ArmPart& p : env_.robot().geometry().parts) {
    scratch_->parts.push_back({std::make_unique<fcl::CollisionObjectd>(p.geometry), std::make_unique<fcl::CollisionObjectd>(p.hull)});
  }
  scratch_->poses.resize(env_.robot().kinematics().link_count());
  scratch_->steps.resize(static_cast<std::size_t>(env_.robot().kinematics().dof()));
  const auto& objects = env_.scene().scene().objects;
  bool any = false;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    for (std::size_t l = 0; l < env_.robot().model().links().size(); ++l) any = any || env_.allowed(i, static_cast<int>(l));
  }
  if (any) {
    for (std::size_t i = 0; i < objects.size(); ++i) scratch_->scene_index[objects[i].get()] = i;
  }
  scratch_->query.env = &env_;
  scratch_->query.scene_index = &scratch_->scene_index;
}

ArmChecker::~ArmChecker() = default;

void ArmChecker::place(const State& s) const {
  Scratch& w = *scratch_;
  env_.robot().kinematics().link_poses(s, w.poses.data());
  const auto& parts = env_.robot().geometry().parts;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const fcl::Transform3d t = to_fcl(w.poses[static_cast<std::size_t>(parts[i].link)] * parts[i].local);
    for (fcl::CollisionObjectd* o : {w.parts[i].exact.get(), w.parts[i].hull.get()}) {
      o->setTransform(t);
      o->computeAABB();
    }
  }
}

bool ArmChecker::touches_scene(std::size_t part) const {
  SceneQuery& q = scratch_->query;
  q.part = &scratch_->parts[part];
  q.link = env_.robot().geometry().parts[part].link;
  q.hit = false;
  env_.scene().scene().manager.collide(scratch_->parts[part].hull.get(), &q, collide_callback);
  return q.hit;
}

bool ArmChecker::check(const State& s) const {
  place(s);
  const Scratch& w = *scratch_;
  for (const auto& [i, k] : env_.robot().self_part_pairs()) {
    if (parts_collide(w.parts[static_cast<std::size_t>(i)], w.parts[static_cast<std::size_t>(k)])) return false;
  }
  for (std::size_t p = 0; p < w.parts.size(); ++p) {
    if (touches_scene(p)) return false;
  }
  return true;
}

std::string ArmChecker::first_contact(const State& s) const {
  place(s);
  const Scratch& w = *scratch_;
  const auto& parts = env_.robot().geometry().parts;
  const auto link_name = [&](std::size_t part) { return env_.robot().model().link(parts[part].link).name; };
  for (const auto& [i, k] : env_.robot().self_part_pairs()) {
    const auto a = static_cast<std::size_t>(i), b = static_cast<std::size_t>(k);
    if (parts_collide(w.parts[a], w.parts[b])) return "links '" + link_name(a) + "' and '" + link_name(b) + "'";
  }
  const auto& objects = env_.scene().scene().objects;
  for (std::size_t p = 0; p < w.parts.size(); ++p) {
    for (std::size_t o = 0; o < objects.size(); ++o) {
      if (!env_.allowed(o, parts[p].link) && part_collides_with(w.parts[p], objects[o].get())) {
        return "link '" + link_name(p) + "' and object '" + env_.object_ids()[o] + "'";
      }
    }
  }
  return {};
}

Clearance ArmChecker::compute_clearance(const State& s) const {
  place(s);
  Scratch& w = *scratch_;
  SceneQuery& q = w.query;
  q.distance = std::numeric_limits<double>::infinity();
  for (std::size_t p = 0; p < w.parts.size() && q.distance > 0.0; ++p) {
    q.part = &w.parts[p];
    q.link = env_.robot().geometry().parts[p].link;
    env_.scene().scene().manager.distance(w.parts[p].hull.get(), &q, distance_callback);
  }
  Clearance c;
  c.distance = std::max(0.0, q.distance);
  return c;
}

double ArmChecker::compute_free_radius(const State& s) const {
  // No separate validity check: a positive scene clearance means no scene contact, and a self pair
  // is either measured (a contact gives 0) or its bounding spheres are apart.
  double r = compute_clearance(s).distance;
  if (r <= 0.0) return 0.0;
  const Scratch& w = *scratch_;
  const auto& parts = env_.robot().geometry().parts;
  for (const auto& [i, k] : env_.robot().self_part_pairs()) {
    // Both links may move: half their distance. Their bounding spheres' gap bounds it from below,
    // so a pair that cannot lower r costs no distance query.
    const ArmPart &a = parts[static_cast<std::size_t>(i)], &b = parts[static_cast<std::size_t>(k)];
    const Eigen::Vector3d ca = w.poses[static_cast<std::size_t>(a.link)] * a.center;
    const Eigen::Vector3d cb = w.poses[static_cast<std::size_t>(b.link)] * b.center;
    if (0.5 * ((ca - cb).norm() - a.radius - b.radius) >= r) continue;
    const PartObjects& pb = w.parts[static_cast<std::size_t>(k)];
    const double d = part_distance(w.parts[static_cast<std::size_t>(i)], pb.hull.get(), pb.exact.get(), pb.has_hull());
    if (d <= 0.0) return 0.0;
    r = std::min(r, 0.5 * d);
  }
  return r;
}

const double* ArmChecker::joint_steps(const State& a, const State& b) const {
  arm_joint_steps(env_.robot().kinematics(), a, b, scratch_->steps.data());
  return scratch_->steps.data();
}

double ArmChecker::compute_motion_bound(const State& a, const State& b) const {
  // Joint-space interpolation moves each joint at a constant rate; a point's speed is at most the
  // sum over joints of rate x radius (docs/arms.md, "Certification").
  const std::vector<double>& radii = env_.robot().motion_radii();
  const double* steps = joint_steps(a, b);
  return ArmMotionCoefficients::dot(radii.data(), steps, static_cast<int>(radii.size()));
}

// Over the segment's share t, part p moves at most t * v_p (v_p: its coefficients times the joint
// steps), and a self pair relative to each other at most t * v_pair; each is free while that stays
// below its distance at s, so the share is the least distance / v. A part or pair no group joint
// moves keeps its distance everywhere: the state's validity covers it (it is the same at the start).
double ArmChecker::compute_free_share(const State& s, const State& a, const State& b) const {
  place(s);
  const double* steps = joint_steps(a, b);
  double share = std::numeric_limits<double>::infinity();
  if (!scene_share(steps, share) || !self_share(steps, share)) return 0.0;
  return share;
}

bool ArmChecker::scene_share(const double* steps, double& share) const {
  Scratch& w = *scratch_;
  const ArmMotionCoefficients& c = env_.robot().motion_coefficients();
  SceneQuery& q = w.query;
  const auto n = static_cast<std::size_t>(c.joints);
  // Distal parts first: they move most, so their share bounds the rest's queries soonest.
  for (std::size_t p = w.parts.size(); p-- > 0;) {
    if (c.part_moves[p] == 0) continue;
    const double v = ArmMotionCoefficients::dot(&c.part[p * n], steps, c.joints);
    q.part = &w.parts[p];
    q.link = env_.robot().geometry().parts[p].link;
    if (v <= 0.0) {  // still along this segment: only its contact matters
      if (touches_scene(p)) return false;
      continue;
    }
    // Only a distance below share * v can lower the share: the broad phase prunes beyond it.
    q.distance = share * v;
    env_.scene().scene().manager.distance(w.parts[p].hull.get(), &q, distance_callback);
    if (q.distance <= 0.0) return false;
    share = std::min(share, q.distance / v);
  }
  return true;
}

bool ArmChecker::self_share(const double* steps, double& share) const {
  const Scratch& w = *scratch_;
  const ArmMotionCoefficients& c = env_.robot().motion_coefficients();
  const auto& parts = env_.robot().geometry().parts;
  const auto& pairs = env_.robot().self_part_pairs();
  const auto n = static_cast<std::size_t>(c.joints);
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    if (c.pair_moves[i] == 0) continue;
    const auto ia = static_cast<std::size_t>(pairs[i].first), ib = static_cast<std::size_t>(pairs[i].second);
    const double v = ArmMotionCoefficients::dot(&c.pair[i * n], steps, c.joints);
    // The bounding spheres' gap bounds the distance from below: a pair that cannot lower the share
    // (or, still along this segment, cannot touch) costs no query.
    const ArmPart &a = parts[ia], &b = parts[ib];
    const Eigen::Vector3d ca = w.poses[static_cast<std::size_t>(a.link)] * a.center;
    const Eigen::Vector3d cb = w.poses[static_cast<std::size_t>(b.link)] * b.center;
    const double gap = (ca - cb).norm() - a.radius - b.radius;
    if (v <= 0.0) {
      if (gap <= 0.0 && parts_collide(w.parts[ia], w.parts[ib])) return false;
      continue;
    }
    if (gap >= share * v) continue;
    const PartObjects& pb = w.parts[ib];
    const double d = part_distance(w.parts[ia], pb.hull.get(), pb.exact.get(), pb.has_hull());
    if (d <= 0.0) return false;
    share = std::min(share, d / v);
  }
  return true;
}

}  // namespace amp::world::detail
