#pragma once
// Shared by the arm tests: forward kinematics by Orocos KDL on a URDF read by urdfdom directly, so
// that AMP's own loader (load_urdf) and kinematics (ArmKinematics) are checked against code they
// share nothing with. The chain is built as kdl_parser builds it: per joint from the root down,
// F = the joint's <origin>, KDL::Joint(name, F.p, F.M * axis, RotAxis | TransAxis) (None when fixed),
// Segment(child link, joint, F).
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <kdl/chain.hpp>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/frames.hpp>
#include <kdl/jntarray.hpp>
#include <urdf_parser/urdf_parser.h>

namespace amp::test {

// The URDF as urdfdom reads it; throws std::runtime_error when it does not parse.
inline urdf::ModelInterfaceSharedPtr read_urdf(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::ostringstream text;
  text << in.rdbuf();
  urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(text.str());
  if (!model) throw std::runtime_error(file.string() + ": urdfdom could not parse it");
  return model;
}

inline KDL::Frame to_kdl(const urdf::Pose& p) {
  return KDL::Frame(KDL::Rotation::Quaternion(p.rotation.x, p.rotation.y, p.rotation.z, p.rotation.w),
                    KDL::Vector(p.position.x, p.position.y, p.position.z));
}

inline Eigen::Isometry3d to_eigen(const KDL::Frame& f) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) t.linear()(r, c) = f.M(r, c);
    t.translation()[r] = f.p[r];
  }
  return t;
}

// A KDL chain from `root` down to `tip`, with the names of its segments' links (root excluded)
// and of its movable joints in KDL's q order.
struct KdlChain {
  KDL::Chain chain;
  std::vector<std::string> links;
  std::vector<std::string> joints;
};

inline KDL::Joint to_kdl_joint(const urdf::Joint& j) {
  const KDL::Frame f = to_kdl(j.parent_to_joint_origin_transform);
  const KDL::Vector axis(j.axis.x, j.axis.y, j.axis.z);
  switch (j.type) {
    case urdf::Joint::REVOLUTE:
    case urdf::Joint::CONTINUOUS: return KDL::Joint(j.name, f.p, f.M * axis, KDL::Joint::RotAxis);
    case urdf::Joint::PRISMATIC: return KDL::Joint(j.name, f.p, f.M * axis, KDL::Joint::TransAxis);
    case urdf::Joint::FIXED: return KDL::Joint(j.name, KDL::Joint::None);
    default: throw std::runtime_error("joint '" + j.name + "': type not supported by the KDL test chain");
  }
}

// Throws std::runtime_error when `tip` does not descend from `root`.
inline KdlChain kdl_chain(const urdf::ModelInterface& model, const std::string& root, const std::string& tip) {
  std::vector<urdf::LinkConstSharedPtr> path;  // tip first
  for (urdf::LinkConstSharedPtr l = model.getLink(tip); l && l->name != root; l = l->getParent()) {
    if (!l->parent_joint) throw std::runtime_error("'" + tip + "' does not descend from '" + root + "'");
    path.push_back(l);
  }
  if (!model.getLink(tip)) throw std::runtime_error("no link '" + tip + "'");
  KdlChain out;
  for (auto it = path.rbegin(); it != path.rend(); ++it) {
    const urdf::Joint& j = *(*it)->parent_joint;
    const KDL::Joint joint = to_kdl_joint(j);
    out.chain.addSegment(KDL::Segment((*it)->name, joint, to_kdl(j.parent_to_joint_origin_transform)));
    out.links.push_back((*it)->name);
    if (joint.getType() != KDL::Joint::None) out.joints.push_back(j.name);
  }
  return out;
}

// Every link's pose in the root frame, through one KDL chain from the root to each leaf link.
class KdlLinkPoses {
 public:
  explicit KdlLinkPoses(const urdf::ModelInterface& model) : root_(model.getRoot()->name) {
    links_.push_back(root_);
    std::vector<urdf::LinkSharedPtr> all;
    model.getLinks(all);
    for (const urdf::LinkSharedPtr& l : all) {
      if (!l->child_links.empty() || l->name == root_) continue;
      chains_.push_back(kdl_chain(model, root_, l->name));
    }
    // Which chain segment gives each link's pose, and each chain's q from the joint list.
    for (std::size_t c = 0; c < chains_.size(); ++c) {
      for (std::size_t s = 0; s < chains_[c].links.size(); ++s) {
        if (index(chains_[c].links[s]) < 0) {
          links_.push_back(chains_[c].links[s]);
          source_.push_back({c, s});
        }
      }
      for (const std::string& j : chains_[c].joints) {
        if (joint_index(j) < 0) joints_.push_back(j);
      }
    }
    for (const KdlChain& c : chains_) {
      std::vector<int> map;
      for (const std::string& j : c.joints) map.push_back(joint_index(j));
      q_map_.push_back(map);
      solvers_.push_back(std::make_shared<KDL::ChainFkSolverPos_recursive>(c.chain));
    }
  }

  // Link names: the root first.
  const std::vector<std::string>& links() const { return links_; }
  // Movable joint names: the order of poses()'s values.
  const std::vector<std::string>& joints() const { return joints_; }
  int index(const std::string& link) const {
    for (std::size_t i = 0; i < links_.size(); ++i) {
      if (links_[i] == link) return static_cast<int>(i);
    }
    return -1;
  }
  int joint_index(const std::string& joint) const {
    for (std::size_t i = 0; i < joints_.size(); ++i) {
      if (joints_[i] == joint) return static_cast<int>(i);
    }
    return -1;
  }

  // out[i]: the pose of links()[i]; `values[k]` is joints()[k]'s value.
  void poses(const std::vector<double>& values, std::vector<KDL::Frame>& out) const {
    out.assign(links_.size(), KDL::Frame::Identity());
    std::vector<std::vector<KDL::Frame>> frames(chains_.size());
    for (std::size_t c = 0; c < chains_.size(); ++c) {
      KDL::JntArray q(chains_[c].chain.getNrOfJoints());
      for (std::size_t k = 0; k < q_map_[c].size(); ++k) q(static_cast<unsigned>(k)) = values[static_cast<std::size_t>(q_map_[c][k])];
      frames[c].resize(chains_[c].chain.getNrOfSegments());
      if (solvers_[c]->JntToCart(q, frames[c]) < 0) throw std::runtime_error("KDL: JntToCart failed");
    }
    for (std::size_t i = 1; i < links_.size(); ++i) out[i] = frames[source_[i - 1].first][source_[i - 1].second];
  }

 private:
  std::string root_;
  std::vector<KdlChain> chains_;
  std::vector<std::string> links_;
  std::vector<std::string> joints_;
  std::vector<std::pair<std::size_t, std::size_t>> source_;  // per non-root link: (chain, segment)
  std::vector<std::vector<int>> q_map_;
  std::vector<std::shared_ptr<KDL::ChainFkSolverPos_recursive>> solvers_;
};

}  // namespace amp::test
