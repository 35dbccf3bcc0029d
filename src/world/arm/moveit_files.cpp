#include "amp/world/moveit_files.hpp"

#include <cmath>
#include <string>

#include "amp/core/error.hpp"
#include "amp/world/yaml_fields.hpp"

namespace amp::world {

namespace {

// shape_msgs/SolidPrimitive's type numbers, and the words robowflex writes instead.
int primitive_type(const YamlFields& p) {
  const std::string t = p.string("type");
  if (t == "box" || t == "1") return 1;
  if (t == "sphere" || t == "2") return 2;
  if (t == "cylinder" || t == "3") return 3;
  if (t == "cone" || t == "4") p.fail("type", "cone primitives are not supported (box, sphere, cylinder are)");
  p.fail("type", "expected box, sphere or cylinder (or 1, 2, 3), got '" + t + "'");
}

// A point as a list [x, y, z] (robowflex) or a mapping {x:, y:, z:} (ROS message).
Eigen::Vector3d point(const YamlFields& f, std::string_view key) {
  const YamlFields v = f.child(key);
  if (v.is_sequence()) return f.vec3(key);
  return {v.number("x"), v.number("y"), v.number("z")};
}

Eigen::Quaterniond orientation(const YamlFields& f, std::string_view key) {
  const YamlFields v = f.child(key);
  Eigen::Quaterniond q;
  if (v.is_sequence()) {
    const std::vector<double> x = f.numbers(key, 4);  // x y z w
    q = Eigen::Quaterniond(x[3], x[0], x[1], x[2]);
  } else {
    q = Eigen::Quaterniond(v.number("w"), v.number("x"), v.number("y"), v.number("z"));
  }
  // Scaled by its largest component first: [1e200, 0, 0, 1e200] has an infinite norm and would
  // normalise to nothing.
  const double largest = q.coeffs().lpNorm<Eigen::Infinity>();
  if (!std::isfinite(largest)) f.fail(key, "the quaternion must be finite");
  if (!(largest > 1e-9)) f.fail(key, "the quaternion must not be zero");
  q.coeffs() /= largest;
  return q.normalized();
}

Eigen::Isometry3d pose_of(const YamlFields& f) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  if (f.has("position")) t.translate(point(f, "position"));
  if (f.has("orientation")) t.rotate(orientation(f, "orientation"));
  return t;
}

Solid primitive_solid(const YamlFields& p, const Eigen::Isometry3d& pose) {
  const int type = primitive_type(p);
  const std::vector<double> d = p.numbers("dimensions");
  const std::size_t want = type == 1 ? 3 : type == 2 ? 1 : 2;
  if (d.size() < want) p.fail("dimensions", "expected " + std::to_string(want) + " values for this shape");
  for (std::size_t i = 0; i < want; ++i) {
    if (!(d[i] > 0.0) || !std::isfinite(d[i])) p.fail("dimensions", "sizes must be positive");
  }
  if (type == 1) return Solid::box(Eigen::Vector3d(d[0], d[1], d[2]), pose);
  if (type == 2) {
    Solid s = Solid::sphere(d[0], Eigen::Vector3d::Zero());
    s.pose = pose;
    return s;
  }
  return Solid::cylinder(d[1], d[0], pose);  // CYLINDER_HEIGHT = 0, CYLINDER_RADIUS = 1
}

Solid mesh_solid(const YamlFields& m, const Eigen::Isometry3d& pose) {
  TriangleMesh mesh;
  const YamlFields vertices = m.child("vertices");
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const YamlFields v = vertices.element(i);
    mesh.vertices.emplace_back(v.number("x"), v.number("y"), v.number("z"));
  }
  const YamlFields triangles = m.child("triangles");
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const YamlFields t = triangles.element(i);
    const std::vector<double> idx = t.numbers("vertex_indices", 3);
    Eigen::Vector3i tri;
    for (int k = 0; k < 3; ++k) {
      if (!(idx[k] >= 0.0 && idx[k] < static_cast<double>(mesh.vertices.size())) || idx[k] != std::floor(idx[k])) {
        t.fail("vertex_indices", "expected indices of the mesh's vertices");
      }
      tri[k] = static_cast<int>(idx[k]);
    }
    mesh.triangles.push_back(tri);
  }
  if (mesh.triangles.empty()) m.fail("triangles", "a mesh needs at least one triangle");
  return Solid::mesh_of(mesh, pose);
}

// The object's shapes, each posed by the object's `pose` (when present) times its own pose.
void add_object(const YamlFields& o, MoveItScene& scene) {
  const std::string id = o.string("id", "");
  if (o.has("operation")) {
    const std::string op = o.string("operation");
    if (op != "0" && op != "ADD" && op != "add") o.fail("operation", "only ADD (0) objects are supported");
  }
  const Eigen::Isometry3d frame = o.has("pose") ? pose_of(o.child("pose")) : Eigen::Isometry3d::Identity();
  const auto shapes = [&](const char* list, const char* poses, auto make) {
    if (!o.has(list)) return;
    const YamlFields items = o.child(list);
    if (items.size() == 0) return;
    const YamlFields ps = o.child(poses);
    if (ps.size() != items.size()) o.fail(poses, "expected one pose per entry of " + std::string(list));
    for (std::size_t i = 0; i < items.size(); ++i) {
      // Each pose finite is not enough: two of 1e308 add up to infinity.
      const Eigen::Isometry3d placed = frame * pose_of(ps.element(i));
      if (!placed.matrix().allFinite()) o.fail(poses, "entry " + std::to_string(i) + ": the pose, with the object's pose, is not finite");
      scene.objects.push_back(make(items.element(i), placed));
      scene.object_ids.push_back(id);
    }
  };
  shapes("primitives", "primitive_poses", primitive_solid);
  shapes("meshes", "mesh_poses", mesh_solid);
  if (o.has("planes") && o.child("planes").size() > 0) o.fail("planes", "plane objects are not supported");
}

JointValues joint_values(const YamlFields& js) {
  JointValues out;
  if (!js.has("name")) return out;
  const YamlFields names = js.child("name");
  const std::vector<double> positions = js.has("position") && js.child("position").size() > 0 ? js.numbers("position")
                                                                                                : std::vector<double>{};
  if (positions.size() != names.size()) js.fail("position", "expected one position per name");
  for (std::size_t i = 0; i < names.size(); ++i) {
    const YAML::Node n = names.element(i).node();
    if (!n.IsScalar()) names.element(i).fail("", "expected a joint name");
    out[n.Scalar()] = positions[i];
  }
  return out;
}

void read_allowed(const YamlFields& acm, AllowedCollisions& out) {
  if (!acm.has("entry_names")) return;
  const YamlFields names = acm.child("entry_names");
  const YamlFields values = acm.child("entry_values");
  if (values.size() != names.size()) acm.fail("entry_values", "expected one row per entry name");
  for (std::size_t i = 0; i < names.size(); ++i) {
    const YamlFields row = values.element(i);
    const YamlFields enabled = row.is_map() ? row.child("enabled") : row;
    if (enabled.size() != names.size()) row.fail("", "expected one value per entry name");
    for (std::size_t j = 0; j < names.size(); ++j) {
      const YAML::Node v = enabled.element(j).node();
      const std::string s = v.IsScalar() ? v.Scalar() : "";
      if (s != "true" && s != "false" && s != "1" && s != "0") enabled.element(j).fail("", "expected true or false");
      if (s == "true" || s == "1") out.allow(names.element(i).node().Scalar(), names.element(j).node().Scalar());
    }
  }
}

// The robot's root stays at the planning frame's origin: a virtual joint that moves it (a mobile
// base) is refused rather than silently ignored.
void check_identity_base(const YamlFields& robot_state) {
  if (!robot_state.has("multi_dof_joint_state")) return;
  const YamlFields m = robot_state.child("multi_dof_joint_state");
  if (!m.has("transforms")) return;
  const YamlFields ts = m.child("transforms");
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const YamlFields t = ts.element(i);
    const Eigen::Vector3d p = t.has("translation") ? point(t, "translation") : Eigen::Vector3d::Zero();
    const Eigen::Quaterniond q = t.has("rotation") ? orientation(t, "rotation") : Eigen::Quaterniond::Identity();
    if (p.norm() > 1e-12 || q.angularDistance(Eigen::Quaterniond::Identity()) > 1e-12) {
      t.fail("", "a virtual joint that moves the robot's root is not supported (the root stays at the origin)");
    }
  }
}

YAML::Node parse_text(const std::string& yaml, const std::filesystem::path& label) {
  try {
    return YAML::Load(yaml);
  } catch (const YAML::Exception& e) {
    throw FileError(label.string() + ": malformed YAML at line " + std::to_string(e.mark.line + 1));
  }
}

}  // namespace

void AllowedCollisions::allow(const std::string& a, const std::string& b) {
  pairs_.emplace(std::min(a, b), std::max(a, b));
}

bool AllowedCollisions::allowed(const std::string& a, const std::string& b) const {
  return pairs_.count({std::min(a, b), std::max(a, b)}) > 0;
}

namespace {

MoveItScene scene_from(const YamlFields& root, const std::filesystem::path& label) {
  if (!root.is_map()) root.fail("", "a PlanningScene must be a YAML mapping");
  MoveItScene scene;
  try {
    if (root.has("world") && root.child("world").has("collision_objects")) {
      const YamlFields objects = root.child("world").child("collision_objects");
      std::set<std::string> ids;
      for (std::size_t i = 0; i < objects.size(); ++i) {
        const YamlFields o = objects.element(i);
        if (!ids.insert(o.string("id", "")).second) o.fail("id", "object id '" + o.string("id", "") + "' appears twice");
        add_object(o, scene);
      }
    }
    if (root.has("allowed_collision_matrix")) read_allowed(root.child("allowed_collision_matrix"), scene.allowed);
    if (root.has("robot_state")) {
      const YamlFields rs = root.child("robot_state");
      if (rs.has("attached_collision_objects") && rs.child("attached_collision_objects").size() > 0) {
        rs.fail("attached_collision_objects", "attached objects are not supported");
      }
      if (rs.has("joint_state")) scene.robot_state = joint_values(rs.child("joint_state"));
      check_identity_base(rs);
    }
  } catch (const FileError&) {
    throw;
  } catch (const Error& e) {  // a shape's own check (Solid::box, ...)
    throw FileError(label.string() + ": " + e.what());
  }
  return scene;
}

MoveItRequest request_from(const YamlFields& root) {
  if (!root.is_map()) root.fail("", "a MotionPlanRequest must be a YAML mapping");
  MoveItRequest r;
  r.group = root.string("group_name");
  r.allowed_planning_time = root.has("allowed_planning_time") ? root.number("allowed_planning_time") : 0.0;
  if (r.allowed_planning_time < 0.0 || !std::isfinite(r.allowed_planning_time)) {
    root.fail("allowed_planning_time", "expected a non-negative number of seconds");
  }
  if (root.has("start_state") && root.child("start_state").has("joint_state")) {
    r.start = joint_values(root.child("start_state").child("joint_state"));
  }
  const YamlFields goals = root.child("goal_constraints");
  if (goals.size() == 0) goals.fail("", "expected one goal");
  if (goals.size() > 1) goals.fail("", "only one goal is supported, got " + std::to_string(goals.size()));
  const YamlFields goal = goals.element(0);
  for (const char* pose_key : {"position_constraints", "orientation_constraints", "visibility_constraints"}) {
    if (goal.has(pose_key) && goal.child(pose_key).size() > 0) {
      goal.fail(pose_key, "pose goals are not supported (give joint_constraints)");
    }
  }
  const YamlFields joints = goal.child("joint_constraints");
  if (joints.size() == 0) joints.fail("", "expected at least one joint constraint");
  for (std::size_t i = 0; i < joints.size(); ++i) {
    const YamlFields c = joints.element(i);
    r.goal.emplace_back(c.string("joint_name"), c.number("position"));
  }
  return r;
}

}  // namespace

MoveItScene parse_moveit_scene(const std::string& yaml, const std::filesystem::path& label) {
  return scene_from(YamlFields(parse_text(yaml, label), label, ""), label);
}

MoveItRequest parse_moveit_request(const std::string& yaml, const std::filesystem::path& label) {
  return request_from(YamlFields(parse_text(yaml, label), label, ""));
}

MoveItScene load_moveit_scene(const std::filesystem::path& file) {
  return scene_from(YamlFields(load_yaml_file(file), file, ""), file);
}

MoveItRequest load_moveit_request(const std::filesystem::path& file) {
  return request_from(YamlFields(load_yaml_file(file), file, ""));
}

}  // namespace amp::world
