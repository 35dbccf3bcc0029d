#pragma once
// An independent validity check for arms in MoveIt scenes, shared by the arm tests
// (arm_validity_oracle_test.cpp compares is_valid with it; tests/problems/arm_planners_test.cpp
// re-checks solved paths with it). It shares no code with AMP's arm loaders or checker: the URDF
// through urdfdom, link poses by KDL (kdl_chain.hpp), link meshes read with assimp's C API and turned
// into FCL OBB-RSS BVHs here, scene objects from the YAML through yaml-cpp, the SRDF's disabled pairs
// through tinyxml2. Pairs checked: every two links with collision geometry, unless the SRDF disables
// them or the scene's allowed_collision_matrix allows them; every link against every scene object,
// unless the matrix allows the two names. FCL's narrow phase, after a bounding-sphere test that only
// skips pairs FCL would find apart (no broad-phase structure).
#include <assimp/cimport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <fcl/fcl.h>
#include <tinyxml2.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "world/arm/kdl_chain.hpp"
#include "support/source_tree.hpp"

namespace amp::test {

// MotionBenchMaker's Panda problems shared beside the source tree (absent on some machines).
inline std::filesystem::path mbm_panda_dir() {
  return std::filesystem::path(AMP_SOURCE_DIR) / ".." / "shared" / "mbm" / "panda";
}

// 7 -> "0007", as MotionBenchMaker numbers its scene and request files.
inline std::string scene_number(int i) {
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "%04d", i);
  return buffer;
}

using Geometry = std::shared_ptr<fcl::CollisionGeometryd>;

struct Part {
  Geometry geometry;
  Eigen::Isometry3d local = Eigen::Isometry3d::Identity();
};

inline fcl::Transform3d to_fcl(const Eigen::Isometry3d& p) {
  fcl::Transform3d t;
  t.matrix() = p.matrix();
  return t;
}

inline Eigen::Isometry3d to_isometry(const urdf::Pose& p) { return to_eigen(to_kdl(p)); }

// assimp's C API: triangulated, every node's meshes under its accumulated transform.
inline void collect(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent, const Eigen::Vector3d& scale,
                    std::vector<fcl::Vector3d>& vertices, std::vector<fcl::Triangle>& triangles) {
  const aiMatrix4x4 transform = parent * node.mTransformation;
  for (unsigned m = 0; m < node.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
    const std::size_t base = vertices.size();
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D p = transform * mesh.mVertices[v];
      vertices.emplace_back(scale.x() * p.x, scale.y() * p.y, scale.z() * p.z);
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices == 3) triangles.emplace_back(base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]);
    }
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) collect(scene, *node.mChildren[c], transform, scale, vertices, triangles);
}

inline Geometry mesh_geometry(const std::filesystem::path& file, const Eigen::Vector3d& scale) {
  const aiScene* scene = aiImportFile(file.c_str(), aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
  if (scene == nullptr) throw std::runtime_error(file.string() + ": assimp: " + aiGetErrorString());
  std::vector<fcl::Vector3d> vertices;
  std::vector<fcl::Triangle> triangles;
  collect(*scene, *scene->mRootNode, aiMatrix4x4(), scale, vertices, triangles);
  aiReleaseImport(scene);
  auto model = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
  model->beginModel();
  model->addSubModel(vertices, triangles);
  model->endModel();
  model->computeLocalAABB();
  return model;
}

// package://NAME/rest as the folder beside the URDF holding NAME/rest (the shared Panda's layout).
inline std::filesystem::path mesh_file(const std::string& uri, const std::filesystem::path& urdf_dir) {
  const std::string package = "package://";
  if (uri.rfind(package, 0) == 0) return urdf_dir / uri.substr(package.size());
  return urdf_dir / uri;
}

// FCL's local AABB, and with it aabb_center and aabb_radius (a sphere that contains the geometry),
// which OracleCheck's bounding-sphere test reads.
inline void bound(fcl::CollisionGeometryd& g) {
  g.computeLocalAABB();
  if (!(g.aabb_radius > 0.0)) throw std::runtime_error("a collision geometry without extent");
}

inline Part collision_part(const urdf::Collision& c, const std::filesystem::path& urdf_dir) {
  Part part;
  part.local = to_isometry(c.origin);
  switch (c.geometry->type) {
    case urdf::Geometry::MESH: {
      const auto& m = static_cast<const urdf::Mesh&>(*c.geometry);
      part.geometry = mesh_geometry(mesh_file(m.filename, urdf_dir), Eigen::Vector3d(m.scale.x, m.scale.y, m.scale.z));
      break;
    }
    case urdf::Geometry::BOX: {
      const auto& b = static_cast<const urdf::Box&>(*c.geometry);
      part.geometry = std::make_shared<fcl::Boxd>(b.dim.x, b.dim.y, b.dim.z);
      break;
    }
    case urdf::Geometry::CYLINDER: {
      const auto& y = static_cast<const urdf::Cylinder&>(*c.geometry);
      part.geometry = std::make_shared<fcl::Cylinderd>(y.radius, y.length);
      break;
    }
    case urdf::Geometry::SPHERE:
      part.geometry = std::make_shared<fcl::Sphered>(static_cast<const urdf::Sphere&>(*c.geometry).radius);
      break;
  }
  bound(*part.geometry);
  return part;
}

inline std::set<std::pair<std::string, std::string>> srdf_disabled(const std::filesystem::path& srdf) {
  tinyxml2::XMLDocument doc;
  if (doc.LoadFile(srdf.c_str()) != tinyxml2::XML_SUCCESS) throw std::runtime_error(srdf.string() + ": not XML");
  std::set<std::pair<std::string, std::string>> out;
  for (const tinyxml2::XMLElement* e = doc.FirstChildElement("robot")->FirstChildElement("disable_collisions"); e != nullptr;
       e = e->NextSiblingElement("disable_collisions")) {
    const std::string a = e->Attribute("link1"), b = e->Attribute("link2");
    out.emplace(std::min(a, b), std::max(a, b));
  }
  return out;
}

// The robot side, built once: link geometry in KDL's link order.
struct OracleRobot {
  urdf::ModelInterfaceSharedPtr urdf;
  std::unique_ptr<KdlLinkPoses> fk;
  std::vector<std::vector<Part>> parts;  // per fk->links()
  std::set<std::pair<std::string, std::string>> disabled;

  OracleRobot(const std::filesystem::path& urdf_file, const std::filesystem::path& srdf_file) : urdf(read_urdf(urdf_file)) {
    fk = std::make_unique<KdlLinkPoses>(*urdf);
    for (const std::string& name : fk->links()) {
      std::vector<Part> link_parts;
      for (const urdf::CollisionSharedPtr& c : urdf->getLink(name)->collision_array) {
        link_parts.push_back(collision_part(*c, urdf_file.parent_path()));
      }
      parts.push_back(std::move(link_parts));
    }
    disabled = srdf_disabled(srdf_file);
  }
};

struct SceneObject {
  std::string id;
  Geometry geometry;
  fcl::Transform3d pose;
};

inline Eigen::Isometry3d yaml_pose(const YAML::Node& p) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  if (p["position"]) t.translation() = Eigen::Vector3d(p["position"][0].as<double>(), p["position"][1].as<double>(), p["position"][2].as<double>());
  if (p["orientation"]) {
    const YAML::Node o = p["orientation"];
    t.linear() = Eigen::Quaterniond(o[3].as<double>(), o[0].as<double>(), o[1].as<double>(), o[2].as<double>()).normalized().toRotationMatrix();
  }
  return t;
}

// The scene's objects and its allowed pairs (either order), robowflex's form.
struct OracleScene {
  std::vector<SceneObject> objects;
  std::set<std::pair<std::string, std::string>> allowed;

  explicit OracleScene(const std::filesystem::path& file) {
    const YAML::Node root = YAML::LoadFile(file.string());
    for (const YAML::Node& o : root["world"]["collision_objects"]) {
      const Eigen::Isometry3d frame = o["pose"] ? yaml_pose(o["pose"]) : Eigen::Isometry3d::Identity();
      for (std::size_t i = 0; i < o["primitives"].size(); ++i) {
        const YAML::Node p = o["primitives"][i];
        const std::string type = p["type"].as<std::string>();
        const YAML::Node d = p["dimensions"];
        SceneObject s{o["id"].as<std::string>(), nullptr, to_fcl(frame * yaml_pose(o["primitive_poses"][i]))};
        if (type == "box") s.geometry = std::make_shared<fcl::Boxd>(d[0].as<double>(), d[1].as<double>(), d[2].as<double>());
        if (type == "cylinder") s.geometry = std::make_shared<fcl::Cylinderd>(d[1].as<double>(), d[0].as<double>());  // [height, radius]
        if (type == "sphere") s.geometry = std::make_shared<fcl::Sphered>(d[0].as<double>());
        if (!s.geometry) throw std::runtime_error(file.string() + ": primitive type " + type + " not in the oracle");
        bound(*s.geometry);
        objects.push_back(std::move(s));
      }
    }
    const YAML::Node acm = root["allowed_collision_matrix"];
    if (acm && acm["entry_names"]) {
      const YAML::Node names = acm["entry_names"];
      for (std::size_t i = 0; i < names.size(); ++i) {
        for (std::size_t j = 0; j < names.size(); ++j) {
          if (acm["entry_values"][i][j].as<bool>()) {
            const std::string a = names[i].as<std::string>(), b = names[j].as<std::string>();
            allowed.emplace(std::min(a, b), std::max(a, b));
          }
        }
      }
    }
  }
  bool allows(const std::string& a, const std::string& b) const { return allowed.count({std::min(a, b), std::max(a, b)}) > 0; }
};

// The independent verdict, with what collided.
struct Verdict {
  bool valid = true;
  std::string contact;
};

class OracleCheck {
 public:
  OracleCheck(const OracleRobot& robot, const OracleScene& scene) : robot_(robot), scene_(scene) {
    const auto& links = robot_.fk->links();
    for (std::size_t a = 0; a < links.size(); ++a) {
      if (robot_.parts[a].empty()) continue;
      for (std::size_t b = a + 1; b < links.size(); ++b) {
        if (robot_.parts[b].empty()) continue;
        const std::pair<std::string, std::string> key{std::min(links[a], links[b]), std::max(links[a], links[b])};
        if (robot_.disabled.count(key) > 0 || scene_.allows(links[a], links[b])) continue;
        link_pairs_.emplace_back(a, b);
      }
      for (std::size_t o = 0; o < scene_.objects.size(); ++o) {
        if (!scene_.allows(links[a], scene_.objects[o].id)) object_pairs_.emplace_back(a, o);
      }
    }
  }

  std::size_t link_pairs() const { return link_pairs_.size(); }

  // `values[k]`: the value of robot.fk->joints()[k].
  Verdict check(const std::vector<double>& values) const {
    robot_.fk->poses(values, frames_);
    const auto& links = robot_.fk->links();
    std::vector<std::vector<fcl::Transform3d>> placed(links.size());
    for (std::size_t l = 0; l < links.size(); ++l) {
      const Eigen::Isometry3d pose = to_eigen(frames_[l]);
      for (const Part& p : robot_.parts[l]) placed[l].push_back(to_fcl(pose * p.local));
    }
    const fcl::CollisionRequestd request;
    for (const auto& [a, b] : link_pairs_) {
      for (std::size_t i = 0; i < robot_.parts[a].size(); ++i) {
        for (std::size_t k = 0; k < robot_.parts[b].size(); ++k) {
          if (apart(*robot_.parts[a][i].geometry, placed[a][i], *robot_.parts[b][k].geometry, placed[b][k])) continue;
          fcl::CollisionResultd result;
          if (fcl::collide(robot_.parts[a][i].geometry.get(), placed[a][i], robot_.parts[b][k].geometry.get(), placed[b][k], request,
                           result) > 0) {
            return {false, "links '" + links[a] + "' and '" + links[b] + "'"};
          }
        }
      }
    }
    for (const auto& [l, o] : object_pairs_) {
      const SceneObject& object = scene_.objects[o];
      for (std::size_t i = 0; i < robot_.parts[l].size(); ++i) {
        if (apart(*robot_.parts[l][i].geometry, placed[l][i], *object.geometry, object.pose)) continue;
        fcl::CollisionResultd result;
        if (fcl::collide(robot_.parts[l][i].geometry.get(), placed[l][i], object.geometry.get(), object.pose, request, result) > 0) {
          return {false, "link '" + links[l] + "' and object '" + object.id + "'"};
        }
      }
    }
    return {};
  }

 private:
  // Whether the two geometries' bounding spheres (bound() above), placed, are more than a
  // micrometre apart: then nothing of them touches and FCL, asked, would say so. Only time is saved.
  static bool apart(const fcl::CollisionGeometryd& a, const fcl::Transform3d& ta, const fcl::CollisionGeometryd& b,
                    const fcl::Transform3d& tb) {
    constexpr double kMargin = 1e-6;  // m
    return (ta * a.aabb_center - tb * b.aabb_center).norm() > a.aabb_radius + b.aabb_radius + kMargin;
  }

  const OracleRobot& robot_;
  const OracleScene& scene_;
  std::vector<std::pair<std::size_t, std::size_t>> link_pairs_;
  std::vector<std::pair<std::size_t, std::size_t>> object_pairs_;
  mutable std::vector<KDL::Frame> frames_;
};

// The request's start_state (robowflex's form), by joint name.
inline std::map<std::string, double> request_start(const std::filesystem::path& request) {
  const YAML::Node js = YAML::LoadFile(request.string())["start_state"]["joint_state"];
  std::map<std::string, double> out;
  for (std::size_t i = 0; i < js["name"].size(); ++i) out[js["name"][i].as<std::string>()] = js["position"][i].as<double>();
  return out;
}

// The request's joint goal (its first goal_constraints entry's joint_constraints), by joint name.
inline std::map<std::string, double> request_goal(const std::filesystem::path& request) {
  const YAML::Node constraints = YAML::LoadFile(request.string())["goal_constraints"][0]["joint_constraints"];
  std::map<std::string, double> out;
  for (const YAML::Node& c : constraints) out[c["joint_name"].as<std::string>()] = c["position"].as<double>();
  return out;
}

// The oracle's joint values (robot.fk->joints() order) for a planning group's configuration: the
// group's joints, named in order, from the configuration; every other movable joint at the
// request's start value (0 when the request does not name it).
class OracleGroup {
 public:
  // Throws std::runtime_error when a group joint is not a movable joint on KDL's chains.
  OracleGroup(const OracleRobot& robot, const std::vector<std::string>& group_joints, const std::map<std::string, double>& start) {
    const auto& joints = robot.fk->joints();
    base_.assign(joints.size(), 0.0);
    for (std::size_t k = 0; k < joints.size(); ++k) {
      if (const auto it = start.find(joints[k]); it != start.end()) base_[k] = it->second;
    }
    for (const std::string& name : group_joints) {
      const int index = robot.fk->joint_index(name);
      if (index < 0) throw std::runtime_error(name + " is not a movable joint on KDL's chains");
      slot_.push_back(static_cast<std::size_t>(index));
    }
  }

  std::size_t dimension() const { return slot_.size(); }

  // `q[k]`: the value of group_joints[k]; `values` is overwritten.
  template <class Vector>
  void values(const Vector& q, std::vector<double>& values) const {
    values = base_;
    for (std::size_t k = 0; k < slot_.size(); ++k) values[slot_[k]] = q[static_cast<int>(k)];
  }

 private:
  std::vector<double> base_;
  std::vector<std::size_t> slot_;
};

}  // namespace amp::test
