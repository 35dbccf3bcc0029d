#include "world/arm/sphere_checker.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "world/arm/arm_geometry.hpp"
#include "world/arm/block_kinematics.hpp"
#include "world/arm/sphere_kernels.hpp"
#include "world/arm/sphere_scene.hpp"

namespace amp::world::detail {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

bool is_sphere(const ArmPart& p) { return p.geometry->getNodeType() == fcl::GEOM_SPHERE; }

// Element-wise maximum of rows [first, first + count) of a row-major table with n columns.
std::vector<double> max_row(const std::vector<double>& table, std::size_t first, std::size_t count, std::size_t n) {
  std::vector<double> row(n, 0.0);
  for (std::size_t i = first; i < first + count; ++i) {
    for (std::size_t k = 0; k < n; ++k) row[k] = std::max(row[k], table[i * n + k]);
  }
  return row;
}

std::size_t padded(std::size_t n) { return (n + kSphereLanes - 1) / kSphereLanes * kSphereLanes; }

double least(const double* v, std::size_t n) { return *std::min_element(v, v + n); }

// Where a point of a link can ever be: within `radius` of `center`, over every configuration. Above
// the topmost movable joint on the link's path from the root nothing moves, so that joint's frame
// origin is fixed, and turns about it keep distances; below it each joint's offset, and the point's
// own, add their lengths at most. A slide on the path leaves it unbounded.
struct Reach {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double radius = std::numeric_limits<double>::infinity();
};

Reach link_reach(const ArmKinematics& k, const std::vector<Eigen::Isometry3d>& poses, int link, const Eigen::Vector3d& point) {
  const ArmModel& m = k.model();
  std::vector<int> path;  // joints from the link up to the root
  for (int l = link; m.link(l).parent_joint >= 0; l = m.joint(m.link(l).parent_joint).parent_link) path.push_back(m.link(l).parent_joint);
  std::size_t top = path.size();  // the topmost movable joint
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (m.joint(path[i]).movable()) top = i;
  }
  Reach r;
  if (top == path.size()) {  // nothing moves it
    r.center = poses[static_cast<std::size_t>(link)] * point;
    r.radius = 0.0;
    return r;
  }
  for (std::size_t i = 0; i <= top; ++i) {
    if (m.joint(path[i]).type == ArmJointType::kPrismatic) return r;
  }
  r.center = poses[static_cast<std::size_t>(m.joint(path[top]).child_link)].translation();
  r.radius = point.norm();
  for (std::size_t i = 0; i < top; ++i) r.radius += m.joint(path[i]).origin.translation().norm();
  return r;
}

}  // namespace

bool sphere_checker_applies(const ArmEnvironment& env) {
  const auto& parts = env.robot().geometry().parts;
  return std::all_of(parts.begin(), parts.end(), is_sphere) && sphere_scene_supported(env.scene().obstacles());
}

// What a checker reads and never writes. Spheres are stored link by link in blocks padded to the
// kernels' lane count (the padding repeats a link's last sphere). Each link has a bounding sphere
// (the coarse level) and the obstacles it may touch; for certification, the largest per-joint motion
// of any sphere of a link (of any sphere pair of a link pair) bounds them all at once.
struct SphereChecker::Model {
  struct Link {
    int link = 0;
    std::size_t part = 0;   // its first sphere in ArmRobot's parts (motion coefficient rows)
    std::size_t block = 0;  // its first lane in the blocks
    std::size_t count = 0, lanes = 0;
    Eigen::Vector3d center = Eigen::Vector3d::Zero();
    double radius = 0.0;
    std::vector<std::size_t> obstacles;  // those the scene does not allow it to touch
    std::vector<std::size_t> reachable;  // of those, the ones within its reach (link_reach)
    std::vector<double> motion;          // per group joint
    bool moves = false;
  };
  struct Pair {
    std::size_t a = 0, b = 0;  // into links
    std::size_t first = 0;     // its sphere pairs: self_part_pairs [first, first + a.count * b.count)
    std::vector<double> motion;
    bool moves = false;
  };
  std::vector<double> x, y, z, r;  // link frame, in blocks
  std::vector<double> link_radius;  // per link, repeated in each of kSphereLanes lanes
  std::size_t lanes = 0, widest = 0;
  std::vector<Link> links;
  std::vector<Pair> pairs;
  SphereScene scene;
  std::size_t joints = 0;
  const SphereKernels* kernels = nullptr;

  Model(const ArmEnvironment& env, const SphereKernels& k);
  void add_links(const ArmEnvironment& env);
  void add_pairs(const ArmEnvironment& env);
};

SphereChecker::Model::Model(const ArmEnvironment& env, const SphereKernels& k)
    : scene(make_sphere_scene(env.scene().obstacles())), kernels(&k) {
  joints = static_cast<std::size_t>(env.robot().kinematics().dof());
  add_links(env);
  add_pairs(env);
}

void SphereChecker::Model::add_links(const ArmEnvironment& env) {
  const auto& parts = env.robot().geometry().parts;
  const ArmMotionCoefficients& c = env.robot().motion_coefficients();
  const ArmKinematics& kinematics = env.robot().kinematics();
  std::vector<Eigen::Isometry3d> poses(kinematics.link_count());
  kinematics.link_poses(State::Zero(kinematics.dof()), poses.data());  // the fixed frames (any state)
  for (std::size_t i = 0; i < parts.size();) {
    Link l;
    l.link = parts[i].link;
    l.part = i;
    l.block = lanes;
    while (i < parts.size() && parts[i].link == l.link) ++i;
    l.count = i - l.part;
    l.lanes = padded(l.count);
    for (std::size_t k = 0; k < l.lanes; ++k) {
      const ArmPart& p = parts[l.part + std::min(k, l.count - 1)];
      x.push_back(p.center.x());
      y.push_back(p.center.y());
      z.push_back(p.center.z());
      r.push_back(p.radius);
    }
    lanes += l.lanes;
    widest = std::max(widest, l.lanes);
    // The bounding sphere: centred on the spheres' box, reaching the farthest sphere's far side.
    Eigen::AlignedBox3d box;
    for (std::size_t s = l.part; s < i; ++s) {
      box.extend(parts[s].center - Eigen::Vector3d::Constant(parts[s].radius));
      box.extend(parts[s].center + Eigen::Vector3d::Constant(parts[s].radius));
    }
    l.center = box.center();
    for (std::size_t s = l.part; s < i; ++s) l.radius = std::max(l.radius, (parts[s].center - l.center).norm() + parts[s].radius);
    link_radius.insert(link_radius.end(), kSphereLanes, l.radius);
    // Obstacles the link may not touch; validity and certification need only those it can reach in
    // some configuration, clearance all of them.
    const Reach reach = link_reach(kinematics, poses, l.link, l.center);
    for (std::size_t o = 0; o < scene.size(); ++o) {
      if (env.allowed(scene.object[o], l.link)) continue;
      l.obstacles.push_back(o);
      const Eigen::Vector3d to(scene.cx[o] - reach.center.x(), scene.cy[o] - reach.center.y(), scene.cz[o] - reach.center.z());
      if (to.norm() - scene.bound[o] <= reach.radius + l.radius) l.reachable.push_back(o);
    }
    l.motion = max_row(c.part, l.part, l.count, joints);
    l.moves = std::any_of(l.motion.begin(), l.motion.end(), [](double v) { return v > 0.0; });
    links.push_back(std::move(l));
  }
}

// ArmRobot lists the sphere pairs of each checked link pair together, in the pair's order, all
// spheres of the first link against all of the second's.
void SphereChecker::Model::add_pairs(const ArmEnvironment& env) {
  const ArmMotionCoefficients& c = env.robot().motion_coefficients();
  std::vector<int> link_slot(env.robot().model().links().size(), -1);
  for (std::size_t i = 0; i < links.size(); ++i) link_slot[static_cast<std::size_t>(links[i].link)] = static_cast<int>(i);
  std::size_t first = 0;
  for (const auto& [la, lb] : env.robot().self_pairs()) {
    Pair p;
    p.a = static_cast<std::size_t>(link_slot[static_cast<std::size_t>(la)]);
    p.b = static_cast<std::size_t>(link_slot[static_cast<std::size_t>(lb)]);
    p.first = first;
    const std::size_t count = links[p.a].count * links[p.b].count;
    p.motion = max_row(c.pair, first, count, joints);
    p.moves = std::any_of(p.motion.begin(), p.motion.end(), [](double v) { return v > 0.0; });
    first += count;
    pairs.push_back(std::move(p));
  }
}

// Per thread: the link poses of the block last placed (a pose block per link, one configuration
// per lane), the links' bounding spheres' centres in every lane (and lane 0's as vectors, for the
// one-state queries), and the world centres of the spheres of each (link, lane) asked for, stamped
// with the placement they belong to.
struct SphereChecker::Scratch {
  explicit Scratch(BlockKinematics k) : kinematics(std::move(k)) {}
  BlockKinematics kinematics;
  std::vector<double> poses;                  // link_count() pose blocks
  std::vector<Eigen::Isometry3d> scalar_poses;  // a block of one's poses (place_one)
  std::vector<double> cx, cy, cz;             // per Model::Link, kSphereLanes lanes
  std::vector<Eigen::Vector3d> link_centers;  // per Model::Link, lane 0
  std::vector<std::uint64_t> stamp;           // per lane, per Model::Link
  std::uint64_t placement = 0;
  std::vector<double> world;  // per lane: x block, y block, z block
  std::vector<double> gaps;   // one link's lanes
  std::vector<double> steps;
};

SphereChecker::SphereChecker(const ArmEnvironment& env, core::Counters& counters, const SphereKernels& kernels)
    : ValidityChecker(counters),
      env_(env),
      model_(std::make_shared<const Model>(env, kernels)),
      scratch_(std::make_unique<Scratch>(BlockKinematics(env.robot().kinematics(), kernels))) {
  Scratch& w = *scratch_;
  const std::size_t links = model_->links.size();
  w.poses.resize(env.robot().kinematics().link_count() * kPoseBlock);
  w.scalar_poses.resize(env.robot().kinematics().link_count());
  w.cx.resize(links * kSphereLanes);
  w.cy.resize(links * kSphereLanes);
  w.cz.resize(links * kSphereLanes);
  w.link_centers.resize(links);
  w.stamp.assign(kSphereLanes * links, 0);
  w.world.resize(kSphereLanes * 3 * model_->lanes);
  w.gaps.resize(model_->widest);
  w.steps.resize(model_->joints);
}

SphereChecker::~SphereChecker() = default;

void SphereChecker::place_block(const State* const* q, std::size_t n) const {
  Scratch& w = *scratch_;
  ++w.placement;
  if (n == 1) {
    place_one(*q[0]);
    return;
  }
  w.kinematics.poses(q, n, w.poses.data());
  for (std::size_t i = 0; i < model_->links.size(); ++i) {
    const Model::Link& l = model_->links[i];
    const std::size_t at = i * kSphereLanes;
    model_->kernels->place_point(&w.poses[static_cast<std::size_t>(l.link) * kPoseBlock], l.center.x(), l.center.y(),
                                 l.center.z(), &w.cx[at], &w.cy[at], &w.cz[at]);
    w.link_centers[i] = Eigen::Vector3d(w.cx[at], w.cy[at], w.cz[at]);
  }
}

// One state: the scalar chain (ArmKinematics), into lane 0 only, which is all that a block of one
// reads. It is the same pose as a block's lane to rounding, and a quarter of the block's work: one
// state at a time is how rrt-connect checks a new node and certification measures a state.
void SphereChecker::place_one(const State& s) const {
  Scratch& w = *scratch_;
  env_.robot().kinematics().link_poses(s, w.scalar_poses.data());
  for (std::size_t i = 0; i < model_->links.size(); ++i) {
    const Model::Link& l = model_->links[i];
    const Eigen::Isometry3d& pose = w.scalar_poses[static_cast<std::size_t>(l.link)];
    double m[12];
    pose_values(pose, m);
    double* block = &w.poses[static_cast<std::size_t>(l.link) * kPoseBlock];
    for (std::size_t e = 0; e < 12; ++e) block[e * kSphereLanes] = m[e];
    const Eigen::Vector3d c = pose * l.center;
    const std::size_t at = i * kSphereLanes;
    w.cx[at] = c.x(), w.cy[at] = c.y(), w.cz[at] = c.z();
    w.link_centers[i] = c;
  }
}

void SphereChecker::place(const State& s) const {
  const State* q = &s;
  place_block(&q, 1);
}

const double* SphereChecker::placed(std::size_t li, std::size_t lane) const {
  Scratch& w = *scratch_;
  const Model& md = *model_;
  const Model::Link& l = md.links[li];
  double* x = w.world.data() + lane * 3 * md.lanes + l.block;
  std::uint64_t& stamp = w.stamp[lane * md.links.size() + li];
  if (stamp != w.placement) {
    const double* pose = &w.poses[static_cast<std::size_t>(l.link) * kPoseBlock];
    double m[12];
    for (std::size_t e = 0; e < 12; ++e) m[e] = pose[e * kSphereLanes + lane];
    md.kernels->place(m, md.x.data() + l.block, md.y.data() + l.block, md.z.data() + l.block, x, x + md.lanes,
                      x + 2 * md.lanes, l.lanes);
    stamp = w.placement;
  }
  return x;
}

const double* SphereChecker::joint_steps(const State& a, const State& b) const {
  arm_joint_steps(env_.robot().kinematics(), a, b, scratch_->steps.data());
  return scratch_->steps.data();
}

std::size_t SphereChecker::compute_block_size() const { return kSphereLanes; }

// The coarse level in every lane at once: each link's bounding sphere against each obstacle it may
// touch; a lane whose bounding sphere reaches the obstacle looks at that link's spheres.
bool SphereChecker::scene_free(std::size_t n) const {
  const Model& md = *model_;
  const Scratch& w = *scratch_;
  double coarse[kSphereLanes];
  for (std::size_t i = 0; i < md.links.size(); ++i) {
    const Model::Link& l = md.links[i];
    const std::size_t at = i * kSphereLanes;
    for (const std::size_t o : l.reachable) {
      // First by the obstacle's bounding ball alone (no rotation), lane by lane.
      bool near = false;
      for (std::size_t k = 0; k < n && !near; ++k) {
        near = !obstacle_beyond(md.scene, o, Eigen::Vector3d(w.cx[at + k], w.cy[at + k], w.cz[at + k]), l.radius);
      }
      if (!near) continue;
      if (n == 1) {  // one lane: the scalar distance is cheaper than four lanes' worth
        coarse[0] = obstacle_distance(md.scene, o, w.link_centers[i]) - l.radius;
      } else {
        md.kernels->obstacle_gaps(md.scene, o, &w.cx[at], &w.cy[at], &w.cz[at], &md.link_radius[at], kSphereLanes, coarse);
      }
      for (std::size_t k = 0; k < n; ++k) {
        if (coarse[k] > 0.0) continue;
        const double* x = placed(i, k);
        md.kernels->obstacle_gaps(md.scene, o, x, x + md.lanes, x + 2 * md.lanes, md.r.data() + l.block, l.lanes,
                                  scratch_->gaps.data());
        if (least(scratch_->gaps.data(), l.lanes) <= 0.0) return false;
      }
    }
  }
  return true;
}

bool SphereChecker::self_free(std::size_t n) const {
  const Model& md = *model_;
  const Scratch& w = *scratch_;
  for (const Model::Pair& p : md.pairs) {
    const Model::Link &a = md.links[p.a], &b = md.links[p.b];
    const double reach = a.radius + b.radius;
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t ia = p.a * kSphereLanes + k, ib = p.b * kSphereLanes + k;
      const double dx = w.cx[ia] - w.cx[ib], dy = w.cy[ia] - w.cy[ib], dz = w.cz[ia] - w.cz[ib];
      if (dx * dx + dy * dy + dz * dz > reach * reach) continue;
      const double* xa = placed(p.a, k);
      const double* xb = placed(p.b, k);
      for (std::size_t i = 0; i < a.count; ++i) {
        md.kernels->sphere_gaps(xa[i], xa[md.lanes + i], xa[2 * md.lanes + i], md.r[a.block + i], xb, xb + md.lanes,
                                xb + 2 * md.lanes, md.r.data() + b.block, b.lanes, scratch_->gaps.data());
        if (least(scratch_->gaps.data(), b.lanes) <= 0.0) return false;
      }
    }
  }
  return true;
}

bool SphereChecker::check(const State& s) const {
  const State* q = &s;
  return check_block(&q, 1);
}

bool SphereChecker::check_block(const State* const* states, std::size_t n) const {
  place_block(states, n);
  return scene_free(n) && self_free(n);
}

double SphereChecker::link_clearance(std::size_t li, double below) const {
  const Model& md = *model_;
  const Model::Link& l = md.links[li];
  double d = below;
  for (const std::size_t o : l.obstacles) {
    if (obstacle_distance(md.scene, o, scratch_->link_centers[li]) - l.radius >= d) continue;
    const double* x = placed(li);
    md.kernels->obstacle_gaps(md.scene, o, x, x + md.lanes, x + 2 * md.lanes, md.r.data() + l.block, l.lanes,
                              scratch_->gaps.data());
    d = std::min(d, least(scratch_->gaps.data(), l.lanes));
  }
  return d;
}

Clearance SphereChecker::compute_clearance(const State& s) const {
  place(s);
  double d = kInf;
  for (std::size_t i = 0; i < model_->links.size() && d > 0.0; ++i) d = link_clearance(i, d);
  Clearance c;
  c.distance = std::max(0.0, d);
  return c;
}

double SphereChecker::compute_free_radius(const State& s) const {
  double r = compute_clearance(s).distance;  // places s
  if (r <= 0.0) return 0.0;
  const Model& md = *model_;
  const Scratch& w = *scratch_;
  for (const Model::Pair& p : md.pairs) {
    const Model::Link &a = md.links[p.a], &b = md.links[p.b];
    // Both links may move: half their distance; the bounding spheres' gap prunes.
    if (0.5 * ((w.link_centers[p.a] - w.link_centers[p.b]).norm() - a.radius - b.radius) >= r) continue;
    const double* xa = placed(p.a);
    const double* xb = placed(p.b);
    for (std::size_t i = 0; i < a.count; ++i) {
      md.kernels->sphere_gaps(xa[i], xa[md.lanes + i], xa[2 * md.lanes + i], md.r[a.block + i], xb, xb + md.lanes,
                              xb + 2 * md.lanes, md.r.data() + b.block, b.lanes, scratch_->gaps.data());
      const double d = least(scratch_->gaps.data(), b.lanes);
      if (d <= 0.0) return 0.0;
      r = std::min(r, 0.5 * d);
    }
  }
  return r;
}

double SphereChecker::compute_motion_bound(const State& a, const State& b) const {
  const std::vector<double>& radii = env_.robot().motion_radii();
  return ArmMotionCoefficients::dot(radii.data(), joint_steps(a, b), static_cast<int>(radii.size()));
}

// As ArmChecker::compute_free_share (docs/arms.md, "Certification"), with spheres: sphere i is free
// for a share d_i / v_i of the segment, d_i its clearance and v_i its motion per unit share. The
// link's bounding sphere and largest motion bound every sphere's d_i / v_i from below, so a link
// whose bound cannot lower the share is not looked into.
double SphereChecker::compute_free_share(const State& s, const State& a, const State& b) const {
  place(s);
  const double* steps = joint_steps(a, b);
  double share = kInf;
  if (!scene_share(steps, share) || !self_share(steps, share)) return 0.0;
  return share;
}

bool SphereChecker::scene_share(const double* steps, double& share) const {
  const Model& md = *model_;
  const Scratch& w = *scratch_;
  const ArmMotionCoefficients& c = env_.robot().motion_coefficients();
  const int n = static_cast<int>(md.joints);
  double* gaps = scratch_->gaps.data();
  // Distal links first: they move most, so their share bounds the rest soonest.
  for (std::size_t li = md.links.size(); li-- > 0;) {
    const Model::Link& l = md.links[li];
    if (!l.moves) continue;  // the same all along: the state's own validity covers it
    const double v_link = ArmMotionCoefficients::dot(l.motion.data(), steps, n);
    for (const std::size_t o : l.reachable) {
      const double enough = share * v_link;  // a gap this wide cannot lower the share
      if (enough < kInf && obstacle_beyond(md.scene, o, w.link_centers[li], l.radius + enough)) continue;
      const double gap = obstacle_distance(md.scene, o, w.link_centers[li]) - l.radius;
      if (gap > 0.0 && gap >= enough) continue;
      const double* x = placed(li);
      md.kernels->obstacle_gaps(md.scene, o, x, x + md.lanes, x + 2 * md.lanes, md.r.data() + l.block, l.lanes, gaps);
      for (std::size_t i = 0; i < l.count; ++i) {
        if (gaps[i] <= 0.0) return false;
        const double v = ArmMotionCoefficients::dot(&c.part[(l.part + i) * md.joints], steps, n);
        if (v > 0.0) share = std::min(share, gaps[i] / v);
      }
    }
  }
  return true;
}

bool SphereChecker::self_share(const double* steps, double& share) const {
  const Model& md = *model_;
  const Scratch& w = *scratch_;
  const ArmMotionCoefficients& c = env_.robot().motion_coefficients();
  const int n = static_cast<int>(md.joints);
  double* gaps = scratch_->gaps.data();
  for (const Model::Pair& p : md.pairs) {
    if (!p.moves) continue;
    const Model::Link &a = md.links[p.a], &b = md.links[p.b];
    const double v_pair = ArmMotionCoefficients::dot(p.motion.data(), steps, n);
    const double reach = a.radius + b.radius + share * v_pair;
    const double apart = (w.link_centers[p.a] - w.link_centers[p.b]).squaredNorm();
    if (reach < kInf && apart > reach * reach) continue;  // cannot lower the share, without a root
    const double gap = std::sqrt(apart) - a.radius - b.radius;
    if (gap > 0.0 && gap >= share * v_pair) continue;
    const double* xa = placed(p.a);
    const double* xb = placed(p.b);
    for (std::size_t i = 0; i < a.count; ++i) {
      md.kernels->sphere_gaps(xa[i], xa[md.lanes + i], xa[2 * md.lanes + i], md.r[a.block + i], xb, xb + md.lanes,
                              xb + 2 * md.lanes, md.r.data() + b.block, b.lanes, gaps);
      for (std::size_t k = 0; k < b.count; ++k) {
        if (gaps[k] <= 0.0) return false;
        const double v = ArmMotionCoefficients::dot(&c.pair[(p.first + i * b.count + k) * md.joints], steps, n);
        if (v > 0.0) share = std::min(share, gaps[k] / v);
      }
    }
  }
  return true;
}

}  // namespace amp::world::detail
