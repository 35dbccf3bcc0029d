// Our SpatialChecker::is_valid against the bare FCL calls it wraps (set the robot's transform,
// update its AABB, query the broad phase with an early-exit callback), on the same geometry and
// the same states. Target: ours <= 1.10x bare.
#include <benchmark/benchmark.h>

#include <fcl/fcl.h>

#include <memory>
#include <vector>

#include "amp/core/rng.hpp"
#include "amp/core/se3_space.hpp"
#include "amp/world/ompl_cfg.hpp"
#include "amp/world/spatial_environment.hpp"
#include "support/source_tree.hpp"

namespace {

using amp::State;
using amp::world::Solid;
using amp::world::SpatialEnvironment;

constexpr int kStates = 1024;

std::shared_ptr<fcl::CollisionGeometryd> geometry(const Solid& s) {
  switch (s.kind) {
    case Solid::Kind::kBox:
      return std::make_shared<fcl::Boxd>(s.size);
    case Solid::Kind::kSphere:
      return std::make_shared<fcl::Sphered>(s.radius);
    case Solid::Kind::kCylinder:
      return std::make_shared<fcl::Cylinderd>(s.radius, s.length);
    case Solid::Kind::kMesh: {
      auto m = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
      std::vector<fcl::Triangle> tris;
      for (const auto& t : s.mesh->triangles) tris.emplace_back(t[0], t[1], t[2]);
      m->beginModel();
      m->addSubModel(s.mesh->vertices, tris);
      m->endModel();
      return m;
    }
  }
  return nullptr;
}

fcl::Transform3d to_fcl(const Eigen::Isometry3d& p) {
  fcl::Transform3d t;
  t.matrix() = p.matrix();
  return t;
}

struct Scene {
  std::shared_ptr<const SpatialEnvironment> env;
  std::vector<State> states;
};

Scene cage_scene() {  // OMPL.app-style: a mesh rod in a mesh world
  const amp::world::Problem p = amp::world::load_ompl_cfg(std::string(AMP_SOURCE_DIR) + "/problems/ompl/cage_window.cfg");
  Scene scene{std::dynamic_pointer_cast<const SpatialEnvironment>(p.environment), {}};
  amp::core::Rng rng(1);
  for (int i = 0; i < kStates; ++i) {
    State s;
    p.space->sample_uniform(rng, s);
    scene.states.push_back(s);
  }
  return scene;
}

Scene boxes_scene() {  // primitives: a box-and-sphere robot among 200 boxes
  std::vector<Solid> obstacles;
  amp::core::Rng rng(2);
  for (int i = 0; i < 200; ++i) {
    Eigen::Isometry3d pose(Eigen::Translation3d(rng.uniform(0, 20), rng.uniform(0, 20), rng.uniform(0, 20)));
    obstacles.push_back(Solid::box({rng.uniform(0.5, 2), rng.uniform(0.5, 2), rng.uniform(0.5, 2)}, pose));
  }
  const Eigen::AlignedBox3d bounds(Eigen::Vector3d(-2, -2, -2), Eigen::Vector3d(22, 22, 22));
  auto world = std::make_shared<const amp::world::SpatialWorld>(std::move(obstacles), bounds);
  Scene scene{std::make_shared<SpatialEnvironment>(
                  world, amp::world::SpatialRobot::rigid({Solid::box({1, 0.3, 0.3}), Solid::sphere(0.3, {0.6, 0, 0})})),
              {}};
  const amp::core::Se3Space space(Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(20), 1.0);
  for (int i = 0; i < kStates; ++i) {
    State s;
    space.sample_uniform(rng, s);
    scene.states.push_back(s);
  }
  return scene;
}

const Scene& scene(int which) {
  static const Scene cage = cage_scene();
  static const Scene boxes = boxes_scene();
  return which == 0 ? cage : boxes;
}

void BM_AmpIsValid(benchmark::State& st) {
  const Scene& sc = scene(static_cast<int>(st.range(0)));
  amp::core::Counters counters;
  auto checker = sc.env->make_checker(counters);
  std::size_t i = 0;
  int valid = 0;
  for (auto _ : st) {
    valid += checker->is_valid(sc.states[i++ % sc.states.size()]);
  }
  benchmark::DoNotOptimize(valid);
  st.counters["cd_calls"] = static_cast<double>(counters.cd_calls());
  st.SetLabel(st.range(0) == 0 ? "cage meshes" : "200 boxes");
}

struct BareData {
  fcl::CollisionRequestd request;
  fcl::CollisionResultd result;
  bool hit = false;
};

bool bare_callback(fcl::CollisionObjectd* a, fcl::CollisionObjectd* b, void* raw) {
  auto* d = static_cast<BareData*>(raw);
  d->result.clear();
  fcl::collide(a, b, d->request, d->result);
  d->hit = d->result.isCollision();
  return d->hit;
}

void BM_BareFcl(benchmark::State& st) {
  const Scene& sc = scene(static_cast<int>(st.range(0)));
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> obstacles, robot;
  std::vector<fcl::CollisionObjectd*> raw;
  for (const Solid& s : sc.env->world().obstacles()) {
    obstacles.push_back(std::make_unique<fcl::CollisionObjectd>(geometry(s), to_fcl(s.pose)));
    raw.push_back(obstacles.back().get());
  }
  fcl::DynamicAABBTreeCollisionManagerd manager;
  manager.registerObjects(raw);
  manager.setup();
  std::vector<Eigen::Isometry3d> local;
  for (const Solid& s : sc.env->robot().link_solids(0)) {
    robot.push_back(std::make_unique<fcl::CollisionObjectd>(geometry(s)));
    local.push_back(s.pose);
  }
  BareData data;
  std::size_t i = 0;
  int valid = 0;
  for (auto _ : st) {
    const State& s = sc.states[i++ % sc.states.size()];
    Eigen::Isometry3d body(Eigen::Translation3d(s.head<3>()));
    body.rotate(Eigen::Quaterniond(s[6], s[3], s[4], s[5]));
    bool free = true;
    for (std::size_t k = 0; k < robot.size() && free; ++k) {
      robot[k]->setTransform(to_fcl(body * local[k]));
      robot[k]->computeAABB();
      data.hit = false;
      manager.collide(robot[k].get(), &data, bare_callback);
      free = !data.hit;
    }
    valid += free;
  }
  benchmark::DoNotOptimize(valid);
  st.SetLabel(st.range(0) == 0 ? "cage meshes" : "200 boxes");
}

BENCHMARK(BM_AmpIsValid)->Arg(0)->Arg(1);
BENCHMARK(BM_BareFcl)->Arg(0)->Arg(1);

}  // namespace
