#include "amp/world/planar_yaml.hpp"

#include <cmath>
#include <memory>
#include <numbers>
#include <string>

#include "amp/core/error.hpp"
#include "amp/core/joint_space.hpp"
#include "amp/world/planar_environment.hpp"
#include "amp/world/planar_world.hpp"

namespace amp::world {

namespace {
constexpr double kDefaultResolution = 0.01;
constexpr double kPi = std::numbers::pi;

// Runs `f`, turning a ParameterError into a FileError at `fields`.`key`.
template <class F>
auto at(const YamlFields& fields, std::string_view key, F f) {
  try {
    return f();
  } catch (const ParameterError& e) {
    const std::string field = fields.path().empty() ? std::string(key) : fields.path() + "." + std::string(key);
    const std::string what = e.what();
    // Messages that already start with the field ("robot.links[1]: ...") are not prefixed twice.
    if (what.rfind(field, 0) == 0) throw FileError(fields.file().string() + ": " + what);
    fields.fail(key, what);
  }
}

Polygon rectangle(const YamlFields& r) {
  r.allow_only({"center", "size", "angle"});
  const Eigen::Vector2d c = r.vec2("center");
  const Eigen::Vector2d size = r.vec2("size");
  if (!(size.x() > 0.0 && size.y() > 0.0)) r.fail("size", "width and height must be positive");
  const double a = r.number("angle", 0.0);
  const Eigen::Vector2d u(std::cos(a), std::sin(a)), v(-std::sin(a), std::cos(a));
  const Eigen::Vector2d hu = 0.5 * size.x() * u, hv = 0.5 * size.y() * v;
  return Polygon{{c - hu - hv, c + hu - hv, c + hu + hv, c - hu + hv}};
}

std::vector<LinkSpec> parse_links(const YamlFields& robot) {
  const YamlFields list = robot.child("links");
  std::vector<LinkSpec> links;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const YamlFields l = list.element(i);
    l.allow_only({"length", "width"});
    links.push_back({l.positive("length"), l.positive("width")});
  }
  if (links.empty()) robot.fail("links", "expected at least one link");
  return links;
}

// Joints of an arm (first_link 0) or of a linkage (joints sit at links 1..n-1). Weight = the reach
// beyond the joint, so that a radian at the shoulder weighs more than one at the wrist.
std::vector<core::Joint> chain_joints(const YamlFields& robot, const std::vector<LinkSpec>& links, int first_link) {
  const int n = static_cast<int>(links.size());
  std::vector<core::Joint> joints;
  for (int i = first_link; i < n; ++i) {
    double reach = 0.0;
    for (int j = i; j < n; ++j) reach += links[j].length;
    std::string name = "q";  // built in two steps: GCC 12 warns (-Wrestrict) about "q" + to_string
    name += std::to_string(i);
    joints.push_back({std::move(name), core::JointKind::kContinuous, -kPi, kPi, reach});
  }
  if (robot.has("limits")) {
    const YamlFields lim = robot.child("limits");
    if (lim.size() != joints.size()) {
      lim.fail("", "expected " + std::to_string(joints.size()) + " [lo, hi] pairs, one per joint, got " +
                       std::to_string(lim.size()));
    }
    for (std::size_t j = 0; j < joints.size(); ++j) {
      const auto v = lim.element(j).as_numbers(2);
      if (!(v[0] < v[1]) || v[1] - v[0] > 2.0 * kPi) lim.element(j).fail("", "need lo < hi and hi - lo <= 2*pi");
      joints[j].kind = core::JointKind::kRevolute;
      joints[j].lo = v[0];
      joints[j].hi = v[1];
    }
  }
  return joints;
}

std::shared_ptr<core::JointSpace> make_space(const YamlFields& root, const PlanarRobot& robot,
                                             const Eigen::AlignedBox2d& b) {
  const YamlFields r = root.child("robot");
  const Eigen::Vector2d lo = b.min(), hi = b.max();
  std::shared_ptr<core::JointSpace> space;
  switch (robot.kind()) {
    case PlanarRobot::Kind::kRigid:
      space = std::make_shared<core::JointSpace>(core::make_se2_space(lo.x(), lo.y(), hi.x(), hi.y(), robot.radius()));
      break;
    case PlanarRobot::Kind::kTranslating:
      space = std::make_shared<core::JointSpace>(core::make_rn_space({lo.x(), lo.y()}, {hi.x(), hi.y()}));
      break;
    case PlanarRobot::Kind::kFixedArm:
      space = at(r, "limits", [&] {
        return std::make_shared<core::JointSpace>("linkage", chain_joints(r, robot.link_specs(), 0));
      });
      break;
    case PlanarRobot::Kind::kFreeLinkage: {
      std::vector<core::Joint> joints = {{"x", core::JointKind::kLinear, lo.x(), hi.x(), 1.0},
                                         {"y", core::JointKind::kLinear, lo.y(), hi.y(), 1.0},
                                         {"theta", core::JointKind::kContinuous, -kPi, kPi, robot.radius()}};
      for (auto& j : chain_joints(r, robot.link_specs(), 1)) joints.push_back(std::move(j));
      space = at(r, "limits", [&] { return std::make_shared<core::JointSpace>("linkage", std::move(joints)); });
      break;
    }
  }
  const double fraction = root.positive("resolution", kDefaultResolution);
  if (fraction > 1.0) root.fail("resolution", "expected a fraction of the space's extent in (0, 1]");
  space->set_resolution(fraction * space->maximum_extent());
  return space;
}
}  // namespace

Shapes2d parse_shapes2d(const YamlFields& list, double min_radius) {
  Shapes2d shapes;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const YamlFields item = list.element(i);
    item.allow_only({"polygon", "circle", "rectangle"});
    if (item.node().size() != 1) item.fail("", "expected exactly one of polygon, circle, rectangle");
    Shapes2d one;
    std::string_view key;
    if (item.has("polygon")) {
      key = "polygon";
      one.polygons.push_back(Polygon{item.child(key).as_points2()});
    } else if (item.has("circle")) {
      key = "circle";
      const YamlFields c = item.child(key);
      c.allow_only({"center", "radius"});
      one.circles.push_back(Circle{c.vec2("center"), min_radius < 0.0 ? c.number("radius") : c.positive("radius")});
    } else {
      key = "rectangle";
      one.polygons.push_back(rectangle(item.child(key)));
    }
    at(item, key, [&] { validate_shapes(one, "", min_radius); });
    shapes.polygons.insert(shapes.polygons.end(), one.polygons.begin(), one.polygons.end());
    shapes.circles.insert(shapes.circles.end(), one.circles.begin(), one.circles.end());
  }
  return shapes;
}

Eigen::AlignedBox2d parse_bounds2d(const YamlFields& root) {
  const YamlFields b = root.child("bounds");
  b.allow_only({"min", "max"});
  const Eigen::Vector2d lo = b.vec2("min"), hi = b.vec2("max");
  if (!(lo.array() < hi.array()).all()) b.fail("", "min must be below max in x and in y");
  return {lo, hi};
}

PlanarRobot parse_planar_robot(const YamlFields& robot) {
  const std::string type = robot.string("type");
  if (type == "rigid2d") {
    robot.allow_only({"type", "shapes"});
    Shapes2d body = parse_shapes2d(robot.child("shapes"));
    if (body.empty()) robot.fail("shapes", "expected at least one shape");
    return at(robot, "shapes", [&] { return PlanarRobot::rigid(std::move(body)); });
  }
  if (type == "disc") {
    robot.allow_only({"type", "radius"});
    return PlanarRobot::translating(Shapes2d{{}, {Circle{{0.0, 0.0}, robot.positive("radius")}}});
  }
  if (type == "point") {
    robot.allow_only({"type"});
    return PlanarRobot::translating(Shapes2d{{}, {Circle{{0.0, 0.0}, 0.0}}});
  }
  if (type == "arm") {
    robot.allow_only({"type", "base", "links", "limits"});
    Pose2 base;
    if (robot.has("base")) {
      const Eigen::Vector3d b = robot.vec3("base");
      base = {b.x(), b.y(), b.z()};
    }
    return at(robot, "links", [&] { return PlanarRobot::fixed_arm(base, parse_links(robot)); });
  }
  if (type == "linkage") {
    robot.allow_only({"type", "links", "limits"});
    return at(robot, "links", [&] { return PlanarRobot::free_linkage(parse_links(robot)); });
  }
  robot.fail("type", "unknown planar robot type '" + type + "' (expected rigid2d, disc, point, arm or linkage)");
}

LoadedWorld parse_planar_world(const YamlFields& root) {
  if (!root.is_map()) root.fail("", "expected a mapping");
  for (const auto& kv : root.node()) {
    const std::string key = kv.first.Scalar();
    bool ok = false;
    for (std::string_view k : kPlanarProblemKeys) ok = ok || k == key;
    if (!ok) root.fail(key, "unknown field in a planar problem");
  }
  const Eigen::AlignedBox2d bounds = parse_bounds2d(root);
  Shapes2d obstacles;  // no `world:` or no `obstacles:` is an empty world
  if (root.has("world")) {
    const YamlFields world = root.child("world");
    world.allow_only({"obstacles"});
    if (world.has("obstacles")) obstacles = parse_shapes2d(world.child("obstacles"));
  }
  PlanarRobot robot = parse_planar_robot(root.child("robot"));
  auto planar = at(root, "world", [&] { return std::make_shared<const PlanarWorld>(std::move(obstacles), bounds); });
  LoadedWorld out;
  out.space = make_space(root, robot, bounds);
  out.environment = std::make_shared<PlanarEnvironment>(std::move(planar), std::move(robot));
  return out;
}

}  // namespace amp::world
