// A small arm of our own (tests/data/arm/two_link: revolute, prismatic, continuous and fixed joints;
// box, cylinder and sphere links) through every part of AMP's arm support: the URDF loader, SRDF
// groups, forward kinematics, self-collision pairs, MoveIt scenes and requests, load_arm_problem
// and its checker, each against values worked out by hand from the files.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numbers>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "amp/core/counters.hpp"
#include "amp/core/joint_space.hpp"
#include "amp/world/arm_environment.hpp"
#include "amp/world/arm_kinematics.hpp"
#include "amp/world/arm_model.hpp"
#include "amp/world/arm_problem.hpp"
#include "amp/world/arm_srdf.hpp"
#include "amp/world/moveit_files.hpp"
#include "support/state_of.hpp"
#include "support/source_tree.hpp"

namespace amp::world {
namespace {

namespace fs = std::filesystem;
using test::st;

constexpr double kPi = std::numbers::pi;
constexpr double kTight = 1e-12;

fs::path data_dir() { return fs::path(AMP_SOURCE_DIR) / "tests" / "data" / "arm" / "two_link"; }

ArmFiles files() {
  return {data_dir() / "two_link.urdf", data_dir() / "two_link.srdf", data_dir() / "scene.yaml", data_dir() / "request.yaml", {}, {}};
}

Eigen::Matrix3d rz(double a) { return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()).toRotationMatrix(); }

void expect_pose(const Eigen::Isometry3d& got, const Eigen::Vector3d& p, const Eigen::Matrix3d& r, const std::string& what) {
  EXPECT_LT((got.translation() - p).cwiseAbs().maxCoeff(), kTight) << what << ": " << got.translation().transpose() << ", expected "
                                                                   << p.transpose();
  EXPECT_LT((got.linear() - r).cwiseAbs().maxCoeff(), kTight) << what << ": rotation\n" << got.linear() << "\nexpected\n" << r;
}

class TwoLinkArm : public ::testing::Test {
 protected:
  void SetUp() override {
    model_ = std::make_shared<const ArmModel>(load_urdf(files().urdf));
    srdf_ = load_srdf(files().srdf);
  }
  int joint(const std::string& name) const {
    const int j = model_->joint_index(name);
    EXPECT_GE(j, 0) << name;
    return j;
  }
  int link(const std::string& name) const {
    const int l = model_->link_index(name);
    EXPECT_GE(l, 0) << name;
    return l;
  }

  std::shared_ptr<const ArmModel> model_;
  Srdf srdf_;
};

TEST_F(TwoLinkArm, LoaderReadsJointTypesLimitsAndAxes) {
  EXPECT_EQ(model_->name(), "two_link");
  ASSERT_EQ(model_->links().size(), 5u);
  ASSERT_EQ(model_->joints().size(), 4u);
  // Depth-first from the root: a chain, so in file order.
  const std::vector<std::string> links{"base", "link1", "link2", "link3", "tool"};
  for (std::size_t i = 0; i < links.size(); ++i) EXPECT_EQ(model_->link(static_cast<int>(i)).name, links[i]);
  const std::vector<std::string> joints{"shoulder", "slide", "wrist", "tool_joint"};
  for (std::size_t i = 0; i < joints.size(); ++i) {
    const ArmJoint& j = model_->joint(static_cast<int>(i));
    EXPECT_EQ(j.name, joints[i]);
    EXPECT_EQ(j.parent_link, static_cast<int>(i));
    EXPECT_EQ(j.child_link, static_cast<int>(i) + 1);
    EXPECT_EQ(j.mimic_joint, -1);
  }
  const ArmJoint& shoulder = model_->joint(joint("shoulder"));
  EXPECT_EQ(shoulder.type, ArmJointType::kRevolute);
  EXPECT_EQ(shoulder.lower, -2.5);
  EXPECT_EQ(shoulder.upper, 2.5);
  EXPECT_TRUE(shoulder.axis.isApprox(Eigen::Vector3d::UnitZ()));
  EXPECT_TRUE(shoulder.origin.translation().isApprox(Eigen::Vector3d(0, 0, 0.1)));
  const ArmJoint& slide = model_->joint(joint("slide"));
  EXPECT_EQ(slide.type, ArmJointType::kPrismatic);
  EXPECT_EQ(slide.lower, 0.0);
  EXPECT_EQ(slide.upper, 0.3);
  EXPECT_TRUE(slide.axis.isApprox(Eigen::Vector3d::UnitX()));
  const ArmJoint& wrist = model_->joint(joint("wrist"));
  EXPECT_EQ(wrist.type, ArmJointType::kContinuous);
  EXPECT_TRUE(wrist.movable());
  const ArmJoint& tool = model_->joint(joint("tool_joint"));
  EXPECT_EQ(tool.type, ArmJointType::kFixed);
  EXPECT_FALSE(tool.movable());
  EXPECT_LT((tool.origin.linear() - rz(kPi / 2)).cwiseAbs().maxCoeff(), kTight);

  // Collision solids in their link frames, with their <origin>s.
  const auto& base = model_->link(link("base")).collision;
  ASSERT_EQ(base.size(), 1u);
  EXPECT_EQ(base[0].kind, Solid::Kind::kBox);
  EXPECT_TRUE(base[0].size.isApprox(Eigen::Vector3d(0.2, 0.2, 0.1)));
  EXPECT_TRUE(base[0].pose.translation().isApprox(Eigen::Vector3d(0, 0, 0.05)));
  const auto& bar = model_->link(link("link2")).collision;
  ASSERT_EQ(bar.size(), 1u);
  EXPECT_EQ(bar[0].kind, Solid::Kind::kCylinder);
  EXPECT_DOUBLE_EQ(bar[0].radius, 0.03);
  EXPECT_DOUBLE_EQ(bar[0].length, 0.2);
  // rpy (0, pi/2, 0) turns the cylinder's z axis onto the link's x axis.
  EXPECT_LT((bar[0].pose.linear() * Eigen::Vector3d::UnitZ() - Eigen::Vector3d::UnitX()).norm(), kTight);
  EXPECT_TRUE(bar[0].pose.translation().isApprox(Eigen::Vector3d(0.1, 0, 0)));
  const auto& ball = model_->link(link("tool")).collision;
  ASSERT_EQ(ball.size(), 1u);
  EXPECT_EQ(ball[0].kind, Solid::Kind::kSphere);
  EXPECT_DOUBLE_EQ(ball[0].radius, 0.03);
}

// Link poses at three configurations (shoulder, slide, wrist), from the URDF's origins:
// base at the root; link1 at (0, 0, 0.1) turned by the shoulder; link2 at link1 * (0.5 + slide, 0,
// 0.05); link3 at link2 * (0.2, 0, 0) turned by the wrist; tool at link3 * (0.4, 0, 0), turned a
// further pi/2.
TEST_F(TwoLinkArm, LinkPosesByHand) {
  const PlanningGroup g = resolve_group(*model_, srdf_, "arm_chain", "two_link.srdf");
  const ArmKinematics k(model_, g, std::vector<double>(model_->joints().size(), 0.0));
  std::vector<Eigen::Isometry3d> p(k.link_count());

  k.link_poses(st({0, 0, 0}), p.data());  // straight along +x
  expect_pose(p[0], {0, 0, 0}, rz(0), "A base");
  expect_pose(p[1], {0, 0, 0.1}, rz(0), "A link1");
  expect_pose(p[2], {0.5, 0, 0.15}, rz(0), "A link2");
  expect_pose(p[3], {0.7, 0, 0.15}, rz(0), "A link3");
  expect_pose(p[4], {1.1, 0, 0.15}, rz(kPi / 2), "A tool");
  EXPECT_LT((k.tip_position(st({0, 0, 0})) - Eigen::Vector3d(1.1, 0, 0.15)).norm(), kTight);

  // (pi/2, 0.3, pi/2): link2 = (0, 0, 0.1) + Rz(pi/2) (0.8, 0, 0.05) = (0, 0.8, 0.15);
  // link3 = link2 + Rz(pi/2) (0.2, 0, 0) = (0, 1.0, 0.15), Rz(pi); tool = link3 + Rz(pi) (0.4, 0, 0)
  // = (-0.4, 1.0, 0.15), Rz(3 pi/2).
  k.link_poses(st({kPi / 2, 0.3, kPi / 2}), p.data());
  expect_pose(p[1], {0, 0, 0.1}, rz(kPi / 2), "B link1");
  expect_pose(p[2], {0, 0.8, 0.15}, rz(kPi / 2), "B link2");
  expect_pose(p[3], {0, 1.0, 0.15}, rz(kPi), "B link3");
  expect_pose(p[4], {-0.4, 1.0, 0.15}, rz(3 * kPi / 2), "B tool");

  // (-1, 0.1, -2): link2 = (0.6 cos 1, -0.6 sin 1, 0.15), Rz(-1); link3 = (0.8 cos 1, -0.8 sin 1,
  // 0.15), Rz(-3); tool = link3 + 0.4 (cos 3, -sin 3, 0), Rz(-3 + pi/2).
  k.link_poses(st({-1, 0.1, -2}), p.data());
  const double c1 = std::cos(1.0), s1 = std::sin(1.0), c3 = std::cos(3.0), s3 = std::sin(3.0);
  expect_pose(p[2], {0.6 * c1, -0.6 * s1, 0.15}, rz(-1), "C link2");
  expect_pose(p[3], {0.8 * c1, -0.8 * s1, 0.15}, rz(-3), "C link3");
  expect_pose(p[4], {0.8 * c1 + 0.4 * c3, -0.8 * s1 - 0.4 * s3, 0.15}, rz(-3 + kPi / 2), "C tool");
}

TEST_F(TwoLinkArm, ChainAndJointGroupsGiveTheSameJointsInModelOrder) {
  const PlanningGroup chain = resolve_group(*model_, srdf_, "arm_chain", "two_link.srdf");
  const PlanningGroup listed = resolve_group(*model_, srdf_, "arm_joints", "two_link.srdf");
  const std::vector<int> expected{joint("shoulder"), joint("slide"), joint("wrist")};  // the fixed tool_joint left out
  EXPECT_EQ(chain.joints, expected);
  EXPECT_EQ(listed.joints, expected);  // listed as wrist, shoulder, slide, tool_joint
  EXPECT_EQ(chain.tip_link, link("tool"));
  EXPECT_EQ(listed.tip_link, link("tool"));  // the wrist's child, then down the fixed tool_joint
  const PlanningGroup outer = resolve_group(*model_, srdf_, "outer", "two_link.srdf");
  EXPECT_EQ(outer.joints, (std::vector<int>{joint("slide"), joint("wrist")}));
}

TEST_F(TwoLinkArm, SelfPairsLeaveOutTheSrdfDisabledPairs) {
  const PlanningGroup g = resolve_group(*model_, srdf_, "arm_chain", "two_link.srdf");
  const ArmRobot robot(ArmKinematics(model_, g, std::vector<double>(4, 0.0)), make_arm_geometry(*model_), srdf_.disabled_collisions);
  // 10 pairs of 5 links, less the 5 the SRDF disables (its pair naming a link the URDF lacks is ignored).
  const std::vector<std::pair<int, int>> expected{{link("base"), link("link2")},
                                                  {link("base"), link("link3")},
                                                  {link("base"), link("tool")},
                                                  {link("link1"), link("link3")},
                                                  {link("link1"), link("tool")}};
  EXPECT_EQ(robot.self_pairs(), expected);
}

TEST(TwoLinkProblem, LoadsSpaceSeedsAndDefaults) {
  const Problem p = load_arm_problem(files());
  const auto& space = dynamic_cast<const core::JointSpace&>(*p.space);
  EXPECT_EQ(space.kind(), "arm");
  ASSERT_EQ(space.dimension(), 3);
  EXPECT_EQ(space.joints()[0].name, "shoulder");
  EXPECT_EQ(space.joints()[0].kind, core::JointKind::kRevolute);
  EXPECT_EQ(space.joints()[0].lo, -2.5);
  EXPECT_EQ(space.joints()[0].hi, 2.5);
  EXPECT_EQ(space.joints()[1].name, "slide");
  EXPECT_EQ(space.joints()[1].kind, core::JointKind::kLinear);
  EXPECT_EQ(space.joints()[1].hi, 0.3);
  EXPECT_EQ(space.joints()[2].name, "wrist");
  EXPECT_EQ(space.joints()[2].kind, core::JointKind::kContinuous);
  ASSERT_EQ(p.seeds.size(), 2u);
  EXPECT_TRUE(p.start().isApprox(st({kPi / 2, 0, 0})));
  EXPECT_TRUE(p.goal().isApprox(st({-kPi / 2, 0.2, 0.5})));
  EXPECT_EQ(p.defaults.planner, "rrt-connect");
  EXPECT_EQ(p.defaults.time_limit_s, 5.0);
  // The scene allows base-tool: one pair fewer than the SRDF leaves.
  const auto& env = dynamic_cast<const ArmEnvironment&>(*p.environment);
  const std::vector<std::pair<int, int>> expected{{0, 2}, {0, 3}, {1, 3}, {1, 4}};
  EXPECT_EQ(env.robot().self_pairs(), expected);
}

// The box spans x in [0.95, 1.05], y in [-0.05, 0.05], z in [0.1, 0.2]; link3's bar spans
// x in [0.7 + slide, 1.1 + slide] along the arm at wrist 0, y and z within 0.02 of (0, 0.15).
TEST(TwoLinkProblem, CheckerSeesTheBoxAndSelfCollisions) {
  const Problem p = load_arm_problem(files());
  core::Counters counters;
  const auto checker = p.environment->make_checker(counters);
  const auto& env = dynamic_cast<const ArmEnvironment&>(*p.environment);
  // Straight along +x: link3 (x 0.7..1.1) crosses the box; the tool's ball (x 1.07..1.13) does not.
  EXPECT_FALSE(checker->is_valid(st({0, 0, 0})));
  EXPECT_EQ(env.first_contact(st({0, 0, 0})), "link 'link3' and object 'obstacle'");
  // Wrist at pi/2: link3 points along +y from x = 0.7, its bar x in [0.68, 0.72]: clear of the box.
  EXPECT_TRUE(checker->is_valid(st({0, 0, kPi / 2})));
  EXPECT_EQ(env.first_contact(st({0, 0, kPi / 2})), "");
  // The same, slid out 0.3: link3 at x in [0.98, 1.02], y in [0, 0.4] enters the box's y <= 0.05.
  EXPECT_FALSE(checker->is_valid(st({0, 0.3, kPi / 2})));
  // Shoulder at pi/2: the whole arm lies along +y, x within 0.05 of 0.
  EXPECT_TRUE(checker->is_valid(st({kPi / 2, 0.3, 0})));
  // Wrist at pi: link3 folds back over link1 (x 0.3..0.7 against link1's 0..0.5): self-collision.
  EXPECT_FALSE(checker->is_valid(st({kPi / 2, 0, kPi})));
  EXPECT_EQ(env.first_contact(st({kPi / 2, 0, kPi})), "links 'link1' and 'link3'");
  EXPECT_EQ(counters.cd_calls(), 5u);  // first_contact counts nothing
  // The reference point is the tool: at the start (pi/2, 0, 0), (0, 1.1, 0.15).
  EXPECT_LT((env.reference_point(p.start()) - Eigen::Vector3d(0, 1.1, 0.15)).norm(), kTight);
}

class TwoLinkFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("amp_two_link_arm_test_" + std::to_string(::getpid()) + "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    for (const char* f : {"two_link.urdf", "two_link.srdf", "scene.yaml", "request.yaml"}) fs::copy_file(data_dir() / f, dir_ / f);
  }
  void TearDown() override { fs::remove_all(dir_); }
  ArmFiles files() const { return {dir_ / "two_link.urdf", dir_ / "two_link.srdf", dir_ / "scene.yaml", dir_ / "request.yaml", {}, {}}; }
  void write(const std::string& name, const std::string& text) const { std::ofstream(dir_ / name) << text; }

  fs::path dir_;
};

// The scene's allowed_collision_matrix may name objects. The box here (x in [1.05, 1.15]) meets both
// link3 (x 0.7..1.1) and the tool's ball (x 1.07..1.13) at (0, 0, 0).
TEST_F(TwoLinkFiles, SceneMayAllowALinkToTouchAnObject) {
  const std::string world = R"(
world:
  collision_objects:
    - id: obstacle
      primitives: [{type: box, dimensions: [0.1, 0.1, 0.1]}]
      primitive_poses: [{position: [1.1, 0, 0.15], orientation: [0, 0, 0, 1]}]
)";
  write("scene.yaml", R"(
allowed_collision_matrix:
  entry_names: [link3, tool, obstacle]
  entry_values: [[false, false, true], [false, false, false], [true, false, false]]
)" + world);
  {
    const Problem p = load_arm_problem(files());
    core::Counters counters;
    EXPECT_FALSE(p.environment->make_checker(counters)->is_valid(st({0, 0, 0})));
    const auto& env = dynamic_cast<const ArmEnvironment&>(*p.environment);
    EXPECT_EQ(env.first_contact(st({0, 0, 0})), "link 'tool' and object 'obstacle'");
    EXPECT_EQ(env.robot().self_pairs().size(), 5u);  // no link pair allowed by this scene
  }
  write("scene.yaml", R"(
allowed_collision_matrix:
  entry_names: [link3, tool, obstacle]
  entry_values: [[false, false, true], [false, false, true], [true, true, false]]
)" + world);
  {
    const Problem p = load_arm_problem(files());
    core::Counters counters;
    const auto checker = p.environment->make_checker(counters);
    EXPECT_TRUE(checker->is_valid(st({0, 0, 0})));
    EXPECT_FALSE(checker->is_valid(st({0, 0, kPi})));  // link1 against link3 still counts
  }
}

// Joints outside the request's group keep their start values: group `outer` (slide, wrist) with
// the shoulder at pi/2 from the start state.
TEST_F(TwoLinkFiles, JointsOutsideTheGroupKeepTheirStartValues) {
  write("request.yaml", R"(
group_name: outer
start_state: {joint_state: {name: [shoulder, slide, wrist], position: [1.5707963267948966, 0.1, 0]}}
goal_constraints: [{joint_constraints: [{joint_name: slide, position: 0.3}, {joint_name: wrist, position: 1}]}]
)");
  const Problem p = load_arm_problem(files());
  ASSERT_EQ(p.space->dimension(), 2);
  EXPECT_TRUE(p.start().isApprox(st({0.1, 0})));
  // Tool at (0, 0.5 + 0.1 + 0.2 + 0.4, 0.15) with the shoulder held at pi/2.
  EXPECT_LT((p.environment->reference_point(p.start()) - Eigen::Vector3d(0, 1.2, 0.15)).norm(), kTight);
}

void expect_same_solids(const MoveItScene& a, const MoveItScene& b) {
  ASSERT_EQ(a.objects.size(), b.objects.size());
  EXPECT_EQ(a.object_ids, b.object_ids);
  for (std::size_t i = 0; i < a.objects.size(); ++i) {
    const Solid& x = a.objects[i];
    const Solid& y = b.objects[i];
    EXPECT_EQ(x.kind, y.kind) << i;
    EXPECT_TRUE(x.size.isApprox(y.size)) << i;
    EXPECT_EQ(x.radius, y.radius) << i;
    EXPECT_EQ(x.length, y.length) << i;
    EXPECT_LT((x.pose.matrix() - y.pose.matrix()).cwiseAbs().maxCoeff(), kTight) << i;
  }
}

// robowflex writes `type: box` and lists; a plain ROS message has `type: 1` and x/y/z(/w) maps.
TEST(MoveItSceneForms, RosMessageFormGivesTheSameSolidsAsRobowflexForm) {
  const std::string robowflex = R"(
world:
  collision_objects:
    - id: crate
      primitives:
        - {type: box, dimensions: [0.1, 0.2, 0.3]}
        - {type: cylinder, dimensions: [0.4, 0.05]}
        - {type: sphere, dimensions: [0.07]}
      primitive_poses:
        - {position: [1, 2, 3], orientation: [0, 0, 0.3826834323650898, 0.9238795325112867]}
        - {position: [-1, 0.5, 0.25], orientation: [0.5, 0.5, 0.5, 0.5]}
        - {position: [0, 0, 1], orientation: [0, 0, 0, 1]}
allowed_collision_matrix:
  entry_names: [crate, tool, base]
  entry_values:
    - [false, true, false]
    - [true, false, false]
    - [false, false, false]
)";
  const std::string ros = R"(
world:
  collision_objects:
    - id: crate
      header: {frame_id: world}
      operation: 0
      primitives:
        - {type: 1, dimensions: [0.1, 0.2, 0.3]}
        - {type: 3, dimensions: [0.4, 0.05]}
        - {type: 2, dimensions: [0.07]}
      primitive_poses:
        - position: {x: 1, y: 2, z: 3}
          orientation: {x: 0, y: 0, z: 0.3826834323650898, w: 0.9238795325112867}
        - position: {x: -1, y: 0.5, z: 0.25}
          orientation: {x: 0.5, y: 0.5, z: 0.5, w: 0.5}
        - position: {x: 0, y: 0, z: 1}
          orientation: {x: 0, y: 0, z: 0, w: 1}
allowed_collision_matrix:
  entry_names: [crate, tool, base]
  entry_values:
    - {enabled: [false, true, false]}
    - {enabled: [true, false, false]}
    - {enabled: [false, false, false]}
  default_entry_names: []
  default_entry_values: []
)";
  const MoveItScene a = parse_moveit_scene(robowflex, "robowflex.yaml");
  const MoveItScene b = parse_moveit_scene(ros, "ros.yaml");
  expect_same_solids(a, b);
  for (const MoveItScene* s : {&a, &b}) {
    EXPECT_TRUE(s->allowed.allowed("tool", "crate"));
    EXPECT_FALSE(s->allowed.allowed("base", "crate"));
    EXPECT_FALSE(s->allowed.allowed("base", "tool"));
  }
  ASSERT_EQ(a.objects.size(), 3u);
  EXPECT_EQ(a.objects[0].kind, Solid::Kind::kBox);
  EXPECT_TRUE(a.objects[0].size.isApprox(Eigen::Vector3d(0.1, 0.2, 0.3)));
  EXPECT_LT((a.objects[0].pose.linear() - rz(kPi / 4)).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(a.objects[1].kind, Solid::Kind::kCylinder);
  EXPECT_DOUBLE_EQ(a.objects[1].length, 0.4);  // dimensions: [height, radius]
  EXPECT_DOUBLE_EQ(a.objects[1].radius, 0.05);
  EXPECT_EQ(a.objects[2].kind, Solid::Kind::kSphere);
  EXPECT_DOUBLE_EQ(a.objects[2].radius, 0.07);
  EXPECT_TRUE(a.objects[2].pose.translation().isApprox(Eigen::Vector3d(0, 0, 1)));
}

// An object's `pose` goes in front of its primitive_poses: world = pose * primitive_pose.
TEST(MoveItSceneForms, ObjectPoseComesBeforePrimitivePoses) {
  const MoveItScene s = parse_moveit_scene(R"(
world:
  collision_objects:
    - id: turned
      pose: {position: [1, 2, 3], orientation: [0, 0, 0.7071067811865476, 0.7071067811865476]}
      primitives: [{type: box, dimensions: [0.5, 0.1, 0.1]}]
      primitive_poses: [{position: [0.5, 0, 0], orientation: [0, 0, 0.7071067811865476, 0.7071067811865476]}]
)",
                                           "pose.yaml");
  ASSERT_EQ(s.objects.size(), 1u);
  // Rz(pi/2) * (0.5, 0, 0) = (0, 0.5, 0) -> (1, 2.5, 3); rotation Rz(pi/2) Rz(pi/2) = Rz(pi).
  EXPECT_LT((s.objects[0].pose.translation() - Eigen::Vector3d(1, 2.5, 3)).norm(), kTight);
  EXPECT_LT((s.objects[0].pose.linear() - rz(kPi)).cwiseAbs().maxCoeff(), kTight);
  EXPECT_EQ(s.object_ids, std::vector<std::string>{"turned"});
}

TEST(MoveItSceneForms, SceneFileReadsObjectsStateAndAllowedPairs) {
  const MoveItScene s = load_moveit_scene(files().scene);
  ASSERT_EQ(s.objects.size(), 1u);
  EXPECT_EQ(s.object_ids[0], "obstacle");
  EXPECT_TRUE(s.objects[0].pose.translation().isApprox(Eigen::Vector3d(1.0, 0, 0.15)));
  EXPECT_TRUE(s.allowed.allowed("tool", "base"));
  EXPECT_FALSE(s.allowed.allowed("base", "base"));
  EXPECT_FALSE(s.allowed.allowed("link3", "obstacle"));
  EXPECT_DOUBLE_EQ(s.robot_state.at("shoulder"), kPi / 2);
  const MoveItRequest r = load_moveit_request(files().request);
  EXPECT_EQ(r.group, "arm_chain");
  EXPECT_EQ(r.allowed_planning_time, 5.0);
  ASSERT_EQ(r.goal.size(), 3u);
  EXPECT_EQ(r.goal[1].first, "slide");
  EXPECT_EQ(r.goal[1].second, 0.2);
}

}  // namespace
}  // namespace amp::world
