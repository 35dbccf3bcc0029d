#include "ompl_app_problem.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/collision.h>
#include <ompl/base/StateValidityChecker.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>

namespace amp::oracle {

namespace ob = ompl::base;
namespace fs = std::filesystem;

namespace {

using Bvh = fcl::BVHModel<fcl::OBBRSSd>;

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

// The `[problem]` section of the INI file; other sections (planner lists, benchmark) do not define
// the problem.
std::map<std::string, std::string> read_problem_keys(const fs::path& cfg) {
  std::ifstream in(cfg);
  if (!in) throw std::runtime_error(cfg.string() + ": cannot open");
  std::map<std::string, std::string> keys;
  std::string line, section;
  while (std::getline(in, line)) {
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#' || t[0] == ';') continue;
    if (t.front() == '[' && t.back() == ']') {
      section = trim(t.substr(1, t.size() - 2));
    } else if (const auto eq = t.find('='); section == "problem" && eq != std::string::npos) {
      keys[trim(t.substr(0, eq))] = trim(t.substr(eq + 1));
    }
  }
  return keys;
}

double number(const std::map<std::string, std::string>& keys, const std::string& key) {
  const auto it = keys.find(key);
  if (it == keys.end()) throw std::runtime_error("cfg: missing [problem] " + key);
  return std::stod(it->second);
}

double number(const std::map<std::string, std::string>& keys, const std::string& key, double fallback) {
  return keys.count(key) ? number(keys, key) : fallback;
}

// Triangles with the scene graph's transforms applied, as OMPL.app's assimpUtil extracts them; the
// importer keeps its default settings (so COLLADA's <up_axis> is applied by assimp, as in OMPL.app).
struct Soup {
  std::vector<fcl::Vector3d> vertices;
  std::vector<fcl::Triangle> triangles;
  Eigen::Vector3d vertex_sum = Eigen::Vector3d::Zero();  // every vertex of every node instance
  std::size_t vertex_count = 0;
};

void gather(const aiScene& scene, const aiNode& node, aiMatrix4x4 transform, Soup& soup) {
  transform *= node.mTransformation;
  for (unsigned m = 0; m < node.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
    const std::size_t base = soup.vertices.size();
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D p = transform * mesh.mVertices[v];
      soup.vertices.emplace_back(p.x, p.y, p.z);
      soup.vertex_sum += soup.vertices.back();
    }
    soup.vertex_count += mesh.mNumVertices;
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices == 3) {  // points and lines bound no volume
        soup.triangles.emplace_back(base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]);
      }
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) gather(scene, *node.mChildren[c], transform, soup);
}

Soup read_mesh(const fs::path& file) {
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(file.string(), aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
  if (scene == nullptr || scene->mRootNode == nullptr) {
    throw std::runtime_error(file.string() + ": assimp: " + importer.GetErrorString());
  }
  Soup soup;
  gather(*scene, *scene->mRootNode, aiMatrix4x4(), soup);
  if (soup.triangles.empty()) throw std::runtime_error(file.string() + ": no triangles");
  return soup;
}

std::shared_ptr<Bvh> make_bvh(const Soup& soup, const Eigen::Vector3d& shift, Eigen::AlignedBox3d& box) {
  std::vector<fcl::Vector3d> v = soup.vertices;
  for (fcl::Vector3d& p : v) {
    p -= shift;
    box.extend(p);
  }
  auto bvh = std::make_shared<Bvh>();
  bvh->beginModel(static_cast<int>(soup.triangles.size()), static_cast<int>(v.size()));
  bvh->addSubModel(v, soup.triangles);
  bvh->endModel();
  bvh->computeLocalAABB();
  return bvh;
}

fs::path mesh_file(const std::map<std::string, std::string>& keys, const std::string& key, const fs::path& dir) {
  const auto it = keys.find(key);
  if (it == keys.end()) throw std::runtime_error("cfg: missing [problem] " + key);
  const fs::path p = it->second;
  return p.is_absolute() ? p : dir / p;
}

// OMPL.app's FCLStateValidityChecker in short: bounds on the reference point, then one FCL query.
class FclChecker final : public ob::StateValidityChecker {
 public:
  FclChecker(ob::SpaceInformation* si, std::shared_ptr<Bvh> robot, std::shared_ptr<Bvh> world, bool is_3d)
      : ob::StateValidityChecker(si), robot_(std::move(robot)), world_(std::move(world)), is_3d_(is_3d) {}

  bool isValid(const ob::State* state) const override {
    if (!si_->satisfiesBounds(state)) return false;
    fcl::CollisionRequestd request;
    fcl::CollisionResultd result;
    fcl::collide(robot_.get(), pose(state), world_.get(), fcl::Transform3d::Identity(), request, result);
    return !result.isCollision();
  }

 private:
  fcl::Transform3d pose(const ob::State* state) const {
    fcl::Transform3d tf = fcl::Transform3d::Identity();
    if (is_3d_) {
      const auto* s = state->as<ob::SE3StateSpace::StateType>();
      const auto& q = s->rotation();
      tf.linear() = Eigen::Quaterniond(q.w, q.x, q.y, q.z).toRotationMatrix();
      tf.translation() << s->getX(), s->getY(), s->getZ();
    } else {  // planar: the robot stays at its own z, yaw about z
      const auto* s = state->as<ob::SE2StateSpace::StateType>();
      tf.linear() = Eigen::AngleAxisd(s->getYaw(), Eigen::Vector3d::UnitZ()).toRotationMatrix();
      tf.translation() << s->getX(), s->getY(), 0.0;
    }
    return tf;
  }

  std::shared_ptr<Bvh> robot_, world_;
  bool is_3d_;
};

State pose_from_cfg(const std::map<std::string, std::string>& keys, const std::string& which, bool is_3d) {
  const std::string p = which + ".";
  const double theta = number(keys, p + "theta", 0.0);
  if (!is_3d) {
    State s(3);
    s << number(keys, p + "x"), number(keys, p + "y"), theta;
    return s;
  }
  // OMPL's SO3 setAxisAngle: an unnormalised axis is normalised, a zero axis is the identity.
  ob::SO3StateSpace so3;
  ob::State* r = so3.allocState();
  auto* q = r->as<ob::SO3StateSpace::StateType>();
  q->setAxisAngle(number(keys, p + "axis.x", 1.0), number(keys, p + "axis.y", 0.0), number(keys, p + "axis.z", 0.0),
                  theta);
  State s(7);
  s << number(keys, p + "x"), number(keys, p + "y"), number(keys, p + "z"), q->x, q->y, q->z, q->w;
  so3.freeState(r);
  return s;
}

double unit_uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

}  // namespace

OmplAppProblem::OmplAppProblem(const fs::path& cfg) : keys_(read_problem_keys(cfg)) {
  is_3d_ = keys_.count("start.z") > 0;
  const Soup robot = read_mesh(mesh_file(keys_, "robot", cfg.parent_path()));
  const Soup world = read_mesh(mesh_file(keys_, "world", cfg.parent_path()));
  // OMPL.app's robot frame is the mean of its vertices; planar robots keep their own z.
  robot_shift_ = robot.vertex_sum / static_cast<double>(robot.vertex_count);
  if (!is_3d_) robot_shift_.z() = 0.0;
  auto robot_bvh = make_bvh(robot, robot_shift_, robot_box_);
  auto world_bvh = make_bvh(world, Eigen::Vector3d::Zero(), world_box_);
  robot_triangles_ = robot.triangles.size();
  world_triangles_ = world.triangles.size();

  // volume.* when given, else the world's bounding box (OMPL.app's inferred bounds, factor 1, add 0).
  const int dims = is_3d_ ? 3 : 2;
  const char* axes[] = {"x", "y", "z"};
  volume_ = Eigen::AlignedBox3d(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
  ob::RealVectorBounds bounds(dims);
  for (int i = 0; i < dims; ++i) {
    bounds.setLow(i, number(keys_, std::string("volume.min.") + axes[i], world_box_.min()[i]));
    bounds.setHigh(i, number(keys_, std::string("volume.max.") + axes[i], world_box_.max()[i]));
    volume_.min()[i] = bounds.low[i];
    volume_.max()[i] = bounds.high[i];
  }
  ob::StateSpacePtr space;
  if (is_3d_) {
    auto se3 = std::make_shared<ob::SE3StateSpace>();
    se3->setBounds(bounds);
    space = se3;
  } else {
    auto se2 = std::make_shared<ob::SE2StateSpace>();
    se2->setBounds(bounds);
    space = se2;
  }
  si_ = std::make_shared<ob::SpaceInformation>(space);
  si_->setStateValidityChecker(std::make_shared<FclChecker>(si_.get(), robot_bvh, world_bvh, is_3d_));
  si_->setup();  // default DiscreteMotionValidator, longest valid segment fraction 0.01

  start_ = pose_from_cfg(keys_, "start", is_3d_);
  goal_ = pose_from_cfg(keys_, "goal", is_3d_);
}

OmplAppProblem::~OmplAppProblem() = default;

void OmplAppProblem::to_ompl(const State& s, ob::State* out) const {
  if (is_3d_) {
    auto* t = out->as<ob::SE3StateSpace::StateType>();
    t->setXYZ(s[0], s[1], s[2]);
    t->rotation().x = s[3];
    t->rotation().y = s[4];
    t->rotation().z = s[5];
    t->rotation().w = s[6];
  } else {
    auto* t = out->as<ob::SE2StateSpace::StateType>();
    t->setXY(s[0], s[1]);
    t->setYaw(s[2]);
  }
}

bool OmplAppProblem::is_valid(const State& s) const {
  ob::State* st = si_->allocState();
  to_ompl(s, st);
  const bool ok = si_->isValid(st);
  si_->freeState(st);
  return ok;
}

State OmplAppProblem::from_ompl(const ob::State* s) const {
  if (is_3d_) {
    const auto* t = s->as<ob::SE3StateSpace::StateType>();
    State out(7);
    out << t->getX(), t->getY(), t->getZ(), t->rotation().x, t->rotation().y, t->rotation().z, t->rotation().w;
    return out;
  }
  const auto* t = s->as<ob::SE2StateSpace::StateType>();
  State out(3);
  out << t->getX(), t->getY(), t->getYaw();
  return out;
}

bool OmplAppProblem::in_bounds(const State& s) const {
  ob::State* st = si_->allocState();
  to_ompl(s, st);
  const bool ok = si_->satisfiesBounds(st);
  si_->freeState(st);
  return ok;
}

bool OmplAppProblem::check_motion(const State& a, const State& b, double* last_valid_t) const {
  ob::State* sa = si_->allocState();
  ob::State* sb = si_->allocState();
  to_ompl(a, sa);
  to_ompl(b, sb);
  std::pair<ob::State*, double> last_valid(nullptr, 0.0);
  const bool ok = si_->checkMotion(sa, sb, last_valid);
  if (last_valid_t != nullptr) *last_valid_t = ok ? 1.0 : last_valid.second;
  si_->freeState(sa);
  si_->freeState(sb);
  return ok;
}

State OmplAppProblem::interpolate(const State& a, const State& b, double t) const {
  ob::State* sa = si_->allocState();
  ob::State* sb = si_->allocState();
  to_ompl(a, sa);
  to_ompl(b, sb);
  si_->getStateSpace()->interpolate(sa, sb, t, sa);
  const State out = from_ompl(sa);
  si_->freeState(sa);
  si_->freeState(sb);
  return out;
}

State OmplAppProblem::uniform_state(std::mt19937_64& rng) const {
  const int dims = is_3d_ ? 3 : 2;
  State s(is_3d_ ? 7 : 3);
  for (int i = 0; i < dims; ++i) s[i] = volume_.min()[i] + (volume_.max()[i] - volume_.min()[i]) * unit_uniform(rng);
  constexpr double kPi = std::numbers::pi;
  if (!is_3d_) {
    s[2] = -kPi + 2.0 * kPi * unit_uniform(rng);
    return s;
  }
  const double u1 = unit_uniform(rng), u2 = unit_uniform(rng), u3 = unit_uniform(rng);
  const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
  s[3] = a * std::sin(2.0 * kPi * u2);
  s[4] = a * std::cos(2.0 * kPi * u2);
  s[5] = b * std::sin(2.0 * kPi * u3);
  s[6] = b * std::cos(2.0 * kPi * u3);
  s.tail<4>().normalize();  // OMPL accepts |q| within 1e-9 of 1 only
  return s;
}

bool same_pose(const State& a, const State& b, double tol) {
  if (a.size() != b.size()) return false;
  if (a.size() == 3) {
    const double d = std::remainder(a[2] - b[2], 2.0 * std::numbers::pi);
    return (a.head<2>() - b.head<2>()).cwiseAbs().maxCoeff() <= tol && std::abs(d) <= tol;
  }
  return (a.head<3>() - b.head<3>()).cwiseAbs().maxCoeff() <= tol &&
         std::abs(std::abs(a.tail<4>().dot(b.tail<4>())) - 1.0) <= tol;
}

std::vector<State> read_ompl_path(const fs::path& file, bool is_3d) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot open");
  const int n = is_3d ? 7 : 3;
  std::vector<State> path;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    std::istringstream fields(line);
    std::vector<double> v;
    for (double d; fields >> d;) v.push_back(d);
    if (v.empty()) continue;
    if (static_cast<int>(v.size()) != n) {
      throw std::runtime_error(file.string() + ":" + std::to_string(number) + ": expected " + std::to_string(n) +
                               " values");
    }
    State s = Eigen::Map<const Eigen::VectorXd>(v.data(), n);
    if (is_3d) s.tail<4>().normalize();
    path.push_back(s);
  }
  return path;
}

std::string to_string(const State& s) {
  std::string out = "(";
  char buf[32];
  for (int i = 0; i < s.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%s%.9g", i ? ", " : "", s[i]);
    out += buf;
  }
  return out + ")";
}

}  // namespace amp::oracle
