#include "amp/world/spatial_yaml.hpp"

#include <cmath>
#include <string>

#include "amp/core/error.hpp"
#include "amp/core/joint_space.hpp"
#include "amp/core/se3_space.hpp"
#include "amp/world/spatial_environment.hpp"

namespace amp::world {

namespace {

constexpr double kDefaultResolution = 0.01;

Eigen::Quaterniond rotation_of(const YamlFields& f) {
  if (!f.has("rotation")) return Eigen::Quaterniond::Identity();
  const std::vector<double> q = f.numbers("rotation", 4);
  const Eigen::Quaterniond r(q[3], q[0], q[1], q[2]);
  if (!(r.norm() > 1e-9)) f.fail("rotation", "quaternion [qx, qy, qz, qw] must not be zero");
  return r.normalized();
}

Eigen::Isometry3d pose_of(const YamlFields& f, std::string_view position_key) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  if (f.has(position_key)) pose.translate(f.vec3(position_key));
  pose.rotate(rotation_of(f));
  return pose;
}

Solid parse_solid(const YamlFields& item) {
  if (!item.is_map() || item.node().size() != 1) item.fail("", "expected one of box, sphere, cylinder, mesh");
  // A complex key ("? [a, b]" or "{...}:") is legal YAML; as<std::string>() would throw yaml-cpp's own error.
  const YAML::Node key = item.node().begin()->first;
  if (!key.IsScalar()) item.fail("", "expected one of box, sphere, cylinder, mesh as the key, got a non-scalar key");
  const std::string kind = key.Scalar();
  try {
    if (kind == "box") {
      const YamlFields f = item.child("box");
      f.allow_only({"center", "size", "rotation"});
      const Eigen::Vector3d size = f.vec3("size");
      if (!(size.minCoeff() > 0.0)) f.fail("size", "sizes must be positive");
      return Solid::box(size, pose_of(f, "center"));
    }
    if (kind == "sphere") {
      const YamlFields f = item.child("sphere");
      f.allow_only({"center", "radius"});
      return Solid::sphere(f.positive("radius"), f.vec3("center"));
    }
    if (kind == "cylinder") {
      const YamlFields f = item.child("cylinder");
      f.allow_only({"center", "radius", "length", "rotation"});
      return Solid::cylinder(f.positive("radius"), f.positive("length"), pose_of(f, "center"));
    }
    if (kind == "mesh") {
      const YamlFields f = item.child("mesh");
      f.allow_only({"file", "position", "rotation", "scale", "up"});
      const UpAxis up = f.has("up") ? (f.string("up") == "y" ? UpAxis::kY : f.string("up") == "z" ? UpAxis::kZ
                                                                                                  : UpAxis::kAuto)
                                    : UpAxis::kAuto;
      if (f.has("up") && up == UpAxis::kAuto) f.fail("up", "expected 'y' or 'z', got '" + f.string("up") + "'");
      Eigen::Vector3d scale = Eigen::Vector3d::Ones();
      if (f.has("scale")) {
        if (f.child("scale").is_sequence()) {
          scale = f.vec3("scale");
        } else {
          scale.setConstant(f.positive("scale"));
        }
        if (!(scale.minCoeff() > 0.0)) f.fail("scale", "must be positive");
      }
      const std::filesystem::path file = f.file_path("file");
      TriangleMesh mesh;
      try {
        mesh = load_mesh(file, up);
      } catch (const FileError& e) {
        f.fail("file", e.what());  // the mesh file's own error, placed at the field naming it
      }
      return Solid::mesh_of(mesh, pose_of(f, "position"), scale);
    }
  } catch (const FileError&) {
    throw;
  } catch (const Error& e) {
    item.fail(kind, e.what());
  }
  item.fail("", "unknown shape '" + kind + "', expected box, sphere, cylinder or mesh");
}

std::vector<Solid> parse_solids(const YamlFields& list) {
  std::vector<Solid> solids;
  for (std::size_t i = 0; i < list.size(); ++i) solids.push_back(parse_solid(list.element(i)));
  return solids;
}

ScaraParams parse_scara(const YamlFields& r) {
  r.allow_only({"type", "base", "column_height", "upper_arm", "forearm", "link_radius", "wrist_length", "slide",
                "limits", "tool", "tip"});
  ScaraParams p;
  p.base = r.vec3("base");
  p.column_height = r.positive("column_height");
  p.upper_arm = r.positive("upper_arm");
  p.forearm = r.positive("forearm");
  p.link_radius = r.positive("link_radius");
  p.wrist_length = r.positive("wrist_length", 2.0 * p.link_radius);
  const std::vector<double> slide = r.numbers("slide", 2);
  p.slide_lo = slide[0];
  p.slide_hi = slide[1];
  const YamlFields limits = r.child("limits");
  if (limits.size() != 4) r.fail("limits", "expected 4 [lo, hi] pairs (base yaw, shoulder, elbow, wrist)");
  for (std::size_t i = 0; i < 4; ++i) {
    const std::vector<double> lim = limits.element(i).as_numbers(2);
    p.limits[i] = {lim[0], lim[1]};
  }
  const YamlFields tool = r.child("tool");
  p.tool = parse_solids(tool);
  for (std::size_t i = 0; i < p.tool.size(); ++i) {
    if (p.tool[i].kind != Solid::Kind::kBox) tool.element(i).fail("", "tool items must be boxes");
  }
  if (r.has("tip")) {
    p.tip = r.vec3("tip");
  } else {
    double lowest = 0.0;
    for (const Solid& s : p.tool) lowest = std::min(lowest, s.bounds().min().z());
    p.tip = Eigen::Vector3d(0, 0, lowest);
  }
  try {
    p.validate();
  } catch (const ParameterError& e) {
    r.fail("", e.what());
  }
  return p;
}

std::shared_ptr<const core::Space> scara_space(const ScaraParams& p, double resolution) {
  const double tool_reach = p.tip.head<2>().norm() + p.link_radius;
  const double reach = p.upper_arm + p.forearm + tool_reach;
  std::vector<core::Joint> joints = {
      {"base_yaw", core::JointKind::kRevolute, p.limits[0].first, p.limits[0].second, reach},
      {"slide", core::JointKind::kLinear, p.slide_lo, p.slide_hi, 1.0},
      {"shoulder", core::JointKind::kRevolute, p.limits[1].first, p.limits[1].second, reach},
      {"elbow", core::JointKind::kRevolute, p.limits[2].first, p.limits[2].second, p.forearm + tool_reach},
      {"wrist", core::JointKind::kRevolute, p.limits[3].first, p.limits[3].second, tool_reach},
  };
  return std::make_shared<core::JointSpace>("linkage", std::move(joints), resolution);
}

}  // namespace

LoadedWorld parse_spatial_world(const YamlFields& root) {
  const YamlFields b = root.child("bounds");
  b.allow_only({"min", "max"});
  const Eigen::AlignedBox3d bounds(b.vec3("min"), b.vec3("max"));
  if (!((bounds.max() - bounds.min()).minCoeff() > 0.0)) root.fail("bounds", "min must be below max on every axis");
  const double resolution = root.positive("resolution", kDefaultResolution);
  if (resolution > 1.0) root.fail("resolution", "must be a fraction in (0, 1], got " + std::to_string(resolution));

  std::vector<Solid> obstacles;
  if (root.has("world")) {
    const YamlFields w = root.child("world");
    w.allow_only({"obstacles"});
    if (w.has("obstacles")) obstacles = parse_solids(w.child("obstacles"));
  }
  auto world = std::make_shared<const SpatialWorld>(std::move(obstacles), bounds);

  const YamlFields r = root.child("robot");
  const std::string type = r.string("type");
  LoadedWorld out;
  if (type == "rigid3d") {
    r.allow_only({"type", "shapes"});
    std::vector<Solid> body = parse_solids(r.child("shapes"));
    if (body.empty()) r.fail("shapes", "expected at least one shape");
    SpatialRobot robot = SpatialRobot::rigid(std::move(body));
    out.space = std::make_shared<core::Se3Space>(bounds.min(), bounds.max(), std::max(robot.radius(), 1e-9), 1.0,
                                                 resolution);
    out.environment = std::make_shared<SpatialEnvironment>(world, std::move(robot));
  } else if (type == "sphere") {
    r.allow_only({"type", "radius"});
    SpatialRobot robot = SpatialRobot::sphere(r.positive("radius"));
    std::vector<core::Joint> joints;
    for (int i = 0; i < 3; ++i) {
      joints.push_back({std::string(1, "xyz"[i]), core::JointKind::kLinear, bounds.min()[i], bounds.max()[i], 1.0});
    }
    out.space = std::make_shared<core::JointSpace>("rn", std::move(joints), resolution);
    out.environment = std::make_shared<SpatialEnvironment>(world, std::move(robot));
  } else if (type == "scara") {
    ScaraParams params = parse_scara(r);
    out.space = scara_space(params, resolution);
    out.environment = std::make_shared<SpatialEnvironment>(world, SpatialRobot::scara(std::move(params)));
  } else {
    r.fail("type", "expected rigid3d, sphere or scara, got '" + type + "'");
  }
  return out;
}

}  // namespace amp::world
