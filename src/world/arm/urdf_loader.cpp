// URDF -> ArmModel through urdfdom. urdfdom reports why a file does not parse through
// console_bridge; the message is captured for the one-line error instead of being printed.
#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <cmath>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <utility>

#include "amp/core/error.hpp"
#include "amp/world/arm_model.hpp"
#include "amp/world/mesh_loader.hpp"

namespace amp::world {

namespace {

namespace fs = std::filesystem;

// Keeps the first error console_bridge reports while installed. console_bridge's handler is
// process-wide: a mutex serialises parses, and the previous handler comes back afterwards.
class CapturedErrors : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR && first_.empty()) first_ = text;
  }
  const std::string& first() const { return first_; }

 private:
  std::string first_;
};

std::mutex& parse_mutex() {
  static std::mutex m;
  return m;
}

urdf::ModelInterfaceSharedPtr parse_once(const std::string& xml, console_bridge::OutputHandler* handler,
                                         std::string& error) {
  console_bridge::useOutputHandler(handler);
  urdf::ModelInterfaceSharedPtr model;
  try {
    model = urdf::parseURDF(xml);
  } catch (const std::exception& e) {  // urdfdom throws on some malformed numbers
    error = e.what();
  }
  console_bridge::restorePreviousOutputHandler();
  return model;
}

// Every '%' doubled: see parse_with_urdfdom.
std::string escape_percent(const std::string& xml) {
  std::string out;
  out.reserve(xml.size() + 16);
  for (const char c : xml) {
    out += c;
    if (c == '%') out += '%';
  }
  return out;
}

// urdfdom 3 logs some errors with the file's own text as console_bridge's printf format (a value
// that is not a number goes into the message, the message into CONSOLE_BRIDGE_logError), so a '%'
// in the file crashes the parse (tests/fuzz found it). console_bridge formats only when a handler
// is installed: a file holding '%' is parsed without one, and only if that parse fails is a copy
// with every '%' doubled parsed again, with a handler, for the message.
urdf::ModelInterfaceSharedPtr parse_with_urdfdom(const std::string& xml, std::string& error) {
  const std::lock_guard<std::mutex> lock(parse_mutex());
  CapturedErrors captured;
  const bool has_percent = xml.find('%') != std::string::npos;
  urdf::ModelInterfaceSharedPtr model = parse_once(xml, has_percent ? nullptr : &captured, error);
  if (!model && has_percent) {
    error.clear();
    parse_once(escape_percent(xml), &captured, error);
  }
  if (!model && error.empty()) error = captured.first().empty() ? "urdfdom could not parse it" : captured.first();
  return model;
}

// urdfdom holds a link's children by shared_ptr and does not check that its links form a tree: a
// joint cycle makes a link own itself, and the model then never frees (LeakSanitizer found it).
// Clearing every link's child lists when the model is done with breaks any such cycle.
class ChildListsCleared {
 public:
  explicit ChildListsCleared(urdf::ModelInterfaceSharedPtr model) : model_(std::move(model)) {}
  ChildListsCleared(const ChildListsCleared&) = delete;
  ChildListsCleared& operator=(const ChildListsCleared&) = delete;
  ~ChildListsCleared() {
    if (!model_) return;
    for (auto& [name, link] : model_->links_) {
      link->child_links.clear();
      link->child_joints.clear();
    }
  }

 private:
  urdf::ModelInterfaceSharedPtr model_;
};

Eigen::Isometry3d to_isometry(const urdf::Pose& p) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translate(Eigen::Vector3d(p.position.x, p.position.y, p.position.z));
  const Eigen::Quaterniond q(p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z);
  t.rotate(q.normalized());
  return t;
}

struct Context {
  std::string label;
  fs::path base_dir;
  const UrdfOptions* options;
  std::map<fs::path, std::shared_ptr<const TriangleMesh>> meshes;  // a mesh used twice is read once
  std::set<const urdf::Link*> reached;  // links the walk from the root has entered
};

// `package://NAME/rest`, `file://path` or a path relative to the URDF's folder.
fs::path resolve_mesh(const std::string& uri, const std::string& where, const Context& c) {
  const std::string package = "package://", file = "file://";
  std::vector<fs::path> tried;
  if (uri.rfind(package, 0) == 0) {
    const std::string rest_all = uri.substr(package.size());
    const std::size_t slash = rest_all.find('/');
    const std::string name = rest_all.substr(0, slash);
    const std::string rest = slash == std::string::npos ? std::string() : rest_all.substr(slash + 1);
    std::vector<fs::path> folders{c.base_dir};
    folders.insert(folders.end(), c.options->package_paths.begin(), c.options->package_paths.end());
    for (const fs::path& f : folders) {
      for (const fs::path& candidate : {f / rest, f / name / rest}) {
        tried.push_back(candidate);
        std::error_code ec;
        if (!rest.empty() && fs::is_regular_file(candidate, ec)) return candidate;
      }
    }
  } else {
    const fs::path p = uri.rfind(file, 0) == 0 ? fs::path(uri.substr(file.size())) : fs::path(uri);
    const fs::path candidate = p.is_absolute() ? p : c.base_dir / p;
    tried.push_back(candidate);
    std::error_code ec;
    if (fs::is_regular_file(candidate, ec)) return candidate;
  }
  std::string list;
  for (const fs::path& t : tried) list += (list.empty() ? "" : ", ") + t.string();
  throw FileError(c.label + ": " + where + ": mesh '" + uri + "' not found (tried " + list +
                  "; --package-path adds folders)");
}

Solid collision_solid(const urdf::Collision& col, const std::string& where, Context& c) {
  if (!col.geometry) throw FileError(c.label + ": " + where + ": <collision> without <geometry>");
  const Eigen::Isometry3d origin = to_isometry(col.origin);
  try {
    switch (col.geometry->type) {
      case urdf::Geometry::BOX: {
        const auto& b = static_cast<const urdf::Box&>(*col.geometry);
        return Solid::box(Eigen::Vector3d(b.dim.x, b.dim.y, b.dim.z), origin);
      }
      case urdf::Geometry::SPHERE: {
        const auto& s = static_cast<const urdf::Sphere&>(*col.geometry);
        Solid solid = Solid::sphere(s.radius, Eigen::Vector3d::Zero());
        solid.pose = origin;
        return solid;
      }
      case urdf::Geometry::CYLINDER: {
        const auto& cy = static_cast<const urdf::Cylinder&>(*col.geometry);
        return Solid::cylinder(cy.radius, cy.length, origin);
      }
      case urdf::Geometry::MESH: {
        const auto& m = static_cast<const urdf::Mesh&>(*col.geometry);
        const fs::path path = resolve_mesh(m.filename, where, c).lexically_normal();
        auto& cached = c.meshes[path];
        // ROS reads meshes as assimp gives them, without turning a COLLADA Y-up file (geometric_shapes
        // ignores the up axis), hence UpAxis::kZ.
        if (!cached) cached = std::make_shared<const TriangleMesh>(load_mesh(path, UpAxis::kZ));
        return Solid::mesh_of(*cached, origin, Eigen::Vector3d(m.scale.x, m.scale.y, m.scale.z));
      }
    }
  } catch (const FileError&) {
    throw;
  } catch (const Error& e) {
    throw FileError(c.label + ": " + where + ": " + e.what());
  }
  throw FileError(c.label + ": " + where + ": unknown geometry type");
}

ArmJointType joint_type(const urdf::Joint& j, const Context& c) {
  switch (j.type) {
    case urdf::Joint::REVOLUTE: return ArmJointType::kRevolute;
    case urdf::Joint::CONTINUOUS: return ArmJointType::kContinuous;
    case urdf::Joint::PRISMATIC: return ArmJointType::kPrismatic;
    case urdf::Joint::FIXED: return ArmJointType::kFixed;
    default:
      throw FileError(c.label + ": joint '" + j.name +
                      "': type not supported (revolute, continuous, prismatic and fixed joints are)");
  }
}

ArmJoint make_joint(const urdf::Joint& j, int parent, int child, const Context& c) {
  ArmJoint out;
  out.name = j.name;
  out.type = joint_type(j, c);
  out.parent_link = parent;
  out.child_link = child;
  out.origin = to_isometry(j.parent_to_joint_origin_transform);
  if (out.movable()) {
    const Eigen::Vector3d axis(j.axis.x, j.axis.y, j.axis.z);
    // Scaled by its largest component first: a norm of 1e200 0 0 overflows to infinity and
    // would normalise to zero.
    const double largest = axis.lpNorm<Eigen::Infinity>();
    if (!std::isfinite(largest) || !(largest > 1e-9)) {
      throw FileError(c.label + ": joint '" + j.name + "': axis: must be finite and not zero");
    }
    out.axis = (axis / largest).normalized();
  }
  if (out.type == ArmJointType::kRevolute || out.type == ArmJointType::kPrismatic) {
    if (!j.limits) throw FileError(c.label + ": joint '" + j.name + "': <limit> is required for this joint type");
    out.lower = j.limits->lower;
    out.upper = j.limits->upper;
    if (!(out.lower <= out.upper)) {
      throw FileError(c.label + ": joint '" + j.name + "': limit: lower above upper");
    }
  }
  return out;
}

// Depth-first from the root, children in urdfdom's order (MoveIt's joint numbering).
void add_subtree(const urdf::Link& link, int parent_joint, std::vector<ArmLink>& links, std::vector<ArmJoint>& joints,
                 std::vector<const urdf::Joint*>& mimic_of, Context& c) {
  // urdfdom links its tree by pointers without checking it is one: a joint cycle the root reaches
  // would recurse for ever (tests/fuzz found it), a link with two parent joints enter twice.
  if (!c.reached.insert(&link).second) {
    throw FileError(c.label + ": not a valid URDF: link '" + link.name +
                    "' is reached twice from the root (a joint cycle, or two parent joints)");
  }
  const int index = static_cast<int>(links.size());
  ArmLink out;
  out.name = link.name;
  out.parent_joint = parent_joint;
  for (std::size_t k = 0; k < link.collision_array.size(); ++k) {
    const std::string where = "link '" + link.name + "': collision[" + std::to_string(k) + "]";
    out.collision.push_back(collision_solid(*link.collision_array[k], where, c));
  }
  if (link.collision_array.empty() && link.collision) {
    out.collision.push_back(collision_solid(*link.collision, "link '" + link.name + "': collision", c));
  }
  links.push_back(std::move(out));
  for (std::size_t k = 0; k < link.child_joints.size(); ++k) {
    const urdf::Joint& j = *link.child_joints[k];
    const int joint_index = static_cast<int>(joints.size());
    joints.push_back(make_joint(j, index, -1, c));
    mimic_of.push_back(&j);
    links[static_cast<std::size_t>(index)].child_joints.push_back(joint_index);
    joints[static_cast<std::size_t>(joint_index)].child_link = static_cast<int>(links.size());
    add_subtree(*link.child_links[k], joint_index, links, joints, mimic_of, c);
  }
}

// The offset of the first byte that does not begin a well-formed UTF-8 sequence, or npos. urdfdom
// parses with TinyXML 2.6, which steps over a multi-byte character by its lead byte's length
// without looking for the end of the text: a lead byte near the end made it read past the buffer
// (tests/fuzz found it). URDF files are UTF-8; anything else is refused before TinyXML sees it.
std::size_t first_invalid_utf8(const std::string& text) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  for (std::size_t i = 0; i < text.size();) {
    const unsigned char lead = byte(i);
    std::size_t length = 1;
    if (lead >= 0xC2 && lead <= 0xDF) {
      length = 2;
    } else if (lead >= 0xE0 && lead <= 0xEF) {
      length = 3;
    } else if (lead >= 0xF0 && lead <= 0xF4) {
      length = 4;
    } else if (lead >= 0x80) {
      return i;  // a continuation byte without a lead, or a lead no UTF-8 character has
    }
    if (i + length > text.size()) return i;
    for (std::size_t k = 1; k < length; ++k) {
      if ((byte(i + k) & 0xC0) != 0x80) return i;
    }
    i += length;
  }
  return std::string::npos;
}

}  // namespace

ArmModel::ArmModel(std::string name, std::vector<ArmLink> links, std::vector<ArmJoint> joints)
    : name_(std::move(name)), links_(std::move(links)), joints_(std::move(joints)) {}

int ArmModel::link_index(const std::string& name) const {
  for (std::size_t i = 0; i < links_.size(); ++i) {
    if (links_[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

int ArmModel::joint_index(const std::string& name) const {
  for (std::size_t i = 0; i < joints_.size(); ++i) {
    if (joints_[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

bool ArmModel::in_subtree(int ancestor, int descendant) const {
  for (int l = descendant; l >= 0;) {
    if (l == ancestor) return true;
    const int j = link(l).parent_joint;
    l = j < 0 ? -1 : joint(j).parent_link;
  }
  return false;
}

ArmModel parse_urdf(const std::string& xml, const std::string& label, const fs::path& base_dir,
                    const UrdfOptions& options) {
  if (const std::size_t bad = first_invalid_utf8(xml); bad != std::string::npos) {
    throw FileError(label + ": not a valid URDF: not UTF-8 text (byte " + std::to_string(bad) + ")");
  }
  std::string error;
  const urdf::ModelInterfaceSharedPtr model = parse_with_urdfdom(xml, error);
  const ChildListsCleared freed_afterwards(model);
  if (!model) throw FileError(label + ": not a valid URDF: " + error);
  if (!model->getRoot()) throw FileError(label + ": not a valid URDF: no root link");
  Context c{label, base_dir, &options, {}, {}};
  std::vector<ArmLink> links;
  std::vector<ArmJoint> joints;
  std::vector<const urdf::Joint*> source;
  add_subtree(*model->getRoot(), -1, links, joints, source, c);
  // A link the root does not reach (a cycle apart from the tree) would be left out silently.
  for (const auto& [name, link] : model->links_) {
    if (c.reached.count(link.get()) == 0) {
      throw FileError(label + ": not a valid URDF: link '" + name + "' is not connected to the root link '" +
                      model->getRoot()->name + "'");
    }
  }
  ArmModel out(model->getName(), std::move(links), std::move(joints));
  // Mimic joints name their leader by name, which may come later in the tree: resolve afterwards.
  std::vector<ArmJoint> resolved = out.joints();
  for (std::size_t i = 0; i < source.size(); ++i) {
    if (!source[i]->mimic) continue;
    const int leader = out.joint_index(source[i]->mimic->joint_name);
    if (leader < 0 || leader == static_cast<int>(i)) {
      throw FileError(label + ": joint '" + resolved[i].name + "': mimic: no joint '" + source[i]->mimic->joint_name + "'");
    }
    resolved[i].mimic_joint = leader;
    resolved[i].mimic_multiplier = source[i]->mimic->multiplier;
    resolved[i].mimic_offset = source[i]->mimic->offset;
  }
  return ArmModel(out.name(), out.links(), std::move(resolved));
}

ArmModel load_urdf(const fs::path& file, const UrdfOptions& options) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) throw FileError(file.string() + ": no such file");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw FileError(file.string() + ": cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_urdf(text.str(), file.string(), file.parent_path(), options);
}

}  // namespace amp::world
