// Faulty arm files (copies of tests/data/arm/two_link, each with one fault) through
// load_arm_problem: each gives a FileError whose message is one line naming the file and the field
// or element at fault.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <numbers>
#include <iostream>
#include <sstream>
#include <string>

#include "amp/core/error.hpp"
#include "amp/world/arm_model.hpp"
#include "amp/world/arm_problem.hpp"
#include "amp/world/moveit_files.hpp"
#include "support/source_tree.hpp"

namespace amp::world {
namespace {

namespace fs = std::filesystem;

fs::path data_dir() { return fs::path(AMP_SOURCE_DIR) / "tests" / "data" / "arm" / "two_link"; }

std::string read(const fs::path& file) {
  std::ifstream in(file);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

class ArmBadInput : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("amp_arm_bad_input_test_" + std::to_string(::getpid()) + "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    for (const char* f : {"two_link.urdf", "two_link.srdf", "scene.yaml", "request.yaml"}) fs::copy_file(data_dir() / f, dir_ / f);
  }
  void TearDown() override { fs::remove_all(dir_); }

  ArmFiles files() const { return {dir_ / "two_link.urdf", dir_ / "two_link.srdf", dir_ / "scene.yaml", dir_ / "request.yaml", {}, {}}; }
  // Replaces the one occurrence of `from` in the copy of `name` by `to`.
  void edit(const std::string& name, const std::string& from, const std::string& to) const {
    std::string text = read(dir_ / name);
    const std::size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from << " not in " << name;
    ASSERT_EQ(text.find(from, at + 1), std::string::npos) << from << " more than once in " << name;
    text.replace(at, from.size(), to);
    std::ofstream(dir_ / name) << text;
  }
  // The message of the FileError load_arm_problem throws; checks it is one line holding every part.
  std::string error(std::initializer_list<std::string> parts) const {
    try {
      load_arm_problem(files());
    } catch (const FileError& e) {
      const std::string m = e.what();
      EXPECT_EQ(m.find('\n'), std::string::npos) << m;
      for (const std::string& p : parts) EXPECT_NE(m.find(p), std::string::npos) << "'" << p << "' not in: " << m;
      return m;
    } catch (const std::exception& e) {
      ADD_FAILURE() << "not a FileError: " << e.what();
      return {};
    }
    ADD_FAILURE() << "no error";
    return {};
  }
  std::string path(const char* name) const { return (dir_ / name).string(); }

  fs::path dir_;
};

TEST_F(ArmBadInput, UrdfThatDoesNotParse) {
  // A joint whose child link does not exist: urdfdom refuses the model.
  edit("two_link.urdf", "<child link=\"link2\"/>", "<child link=\"nowhere\"/>");
  const std::string m = error({path("two_link.urdf"), "not a valid URDF"});
  std::cout << "[ message  ] " << m << "\n";
}

TEST_F(ArmBadInput, UrdfThatIsNotXml) {
  edit("two_link.urdf", "</robot>", "");
  const std::string m = error({path("two_link.urdf"), "not a valid URDF"});
  std::cout << "[ message  ] " << m << "\n";
}

// urdfdom puts a value it cannot read into a message it then uses as a printf format: a '%' in the
// file crashed the parse (tests/fuzz found it). The error must be the usual one line, and a file whose
// names hold '%' must still load.
TEST_F(ArmBadInput, UrdfWithPrintfDirectivesInABadValue) {
  edit("two_link.urdf", "<origin xyz=\"0 0 0.1\"", "<origin xyz=\"%s%s%s%s%s%s%s%s%n 0 0.1\"");
  const std::string m = error({path("two_link.urdf"), "not a valid URDF", "%s%s"});
  std::cout << "[ message  ] " << m << "\n";
}

// TinyXML (under urdfdom) read past the end of a file ending in a stray UTF-8 lead byte (tests/fuzz
// found it): text that is not UTF-8 is refused first, naming the byte.
TEST_F(ArmBadInput, UrdfThatIsNotUtf8) {
  edit("two_link.urdf", "</robot>", "</robot>\xff\xff\xff\xf0\n");
  const std::string m = error({path("two_link.urdf"), "not UTF-8"});
  std::cout << "[ message  ] " << m << "\n";
}

// urdfdom links its tree by pointers without checking it is one: a joint from link3 to itself
// made the walk from the root recurse until the stack overflowed (tests/fuzz found it).
TEST_F(ArmBadInput, UrdfWithAJointCycle) {
  edit("two_link.urdf", "</robot>", "<joint name=\"loop\" type=\"fixed\"><parent link=\"link3\"/><child link=\"link3\"/></joint></robot>");
  const std::string m = error({path("two_link.urdf"), "not a valid URDF", "link3"});
  std::cout << "[ message  ] " << m << "\n";
}

// The wrist made its own parent: urdfdom returns the rest of the arm, which loaded as a 3-link arm
// with link3 and the tool silently left out.
TEST_F(ArmBadInput, UrdfWithALinkTheRootDoesNotReach) {
  edit("two_link.urdf", "<parent link=\"link2\"/>", "<parent link=\"link3\"/>");
  const std::string m = error({path("two_link.urdf"), "not a valid URDF", "not connected to the root"});
  std::cout << "[ message  ] " << m << "\n";
}

// A vector's norm of 1e200 overflows: the axis must still come out as (1, 0, 0), the quaternion
// [1e200, 0, 0, 1e200] as a quarter turn about x, and poses that add up to infinity be refused.
TEST_F(ArmBadInput, HugeVectorsNormaliseOrAreRefused) {
  edit("two_link.urdf", "<axis xyz=\"1 0 0\"/>", "<axis xyz=\"1e200 0 0\"/>");
  const ArmModel m = load_urdf(dir_ / "two_link.urdf");
  EXPECT_TRUE(m.joint(m.joint_index("slide")).axis.isApprox(Eigen::Vector3d::UnitX())) << m.joint(m.joint_index("slide")).axis.transpose();
  edit("scene.yaml", "orientation: [0, 0, 0, 1]", "orientation: [1e200, 0, 0, 1e200]");
  const MoveItScene scene = load_moveit_scene(dir_ / "scene.yaml");
  ASSERT_EQ(scene.objects.size(), 1u);
  const Eigen::Matrix3d quarter_x = Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  EXPECT_TRUE(scene.objects[0].pose.linear().isApprox(quarter_x, 1e-12)) << scene.objects[0].pose.linear();
  edit("scene.yaml", "position: [1.0, 0, 0.15]", "position: [1e308, 0, 0.15]");
  std::string text = read(dir_ / "scene.yaml");
  const std::size_t at = text.find("      primitive_poses:");
  ASSERT_NE(at, std::string::npos);
  text.insert(at, "      pose: {position: [1e308, 0, 0], orientation: [0, 0, 0, 1]}\n");
  std::ofstream(dir_ / "scene.yaml") << text;
  const std::string e = error({path("scene.yaml"), "not finite"});
  std::cout << "[ message  ] " << e << "\n";
}

TEST_F(ArmBadInput, UrdfWithMultiByteCharactersLoads) {
  edit("two_link.urdf", "<robot name=\"two_link\"", "<robot name=\"zwei_gelenk_\u00e4\u2713\U0001F916\"");
  EXPECT_NO_THROW(load_arm_problem(files()));
}

TEST_F(ArmBadInput, UrdfWithPercentInANameLoads) {
  edit("two_link.urdf", "<robot name=\"two_link\"", "<robot name=\"two%s_link%n\"");
  EXPECT_NO_THROW(load_arm_problem(files()));
}

TEST_F(ArmBadInput, GroupMissingFromTheSrdf) {
  edit("request.yaml", "group_name: arm_chain", "group_name: legs");
  const std::string m = error({path("two_link.srdf"), "'legs'"});
  std::cout << "[ message  ] " << m << "\n";
}

TEST_F(ArmBadInput, GoalJointNotInTheGroup) {
  edit("request.yaml", "joint_name: slide", "joint_name: elbow");
  const std::string m = error({path("request.yaml"), "goal_constraints", "'elbow'"});
  std::cout << "[ message  ] " << m << "\n";
}

TEST_F(ArmBadInput, GoalJointOfAnotherGroup) {
  edit("request.yaml", "group_name: arm_chain", "group_name: outer");
  const std::string m = error({path("request.yaml"), "goal_constraints", "'shoulder'", "'outer'"});
  std::cout << "[ message  ] " << m << "\n";
}

TEST_F(ArmBadInput, GoalOutsideTheJointLimits) {
  edit("request.yaml", "position: 0.2", "position: 0.45");  // slide: limits [0, 0.3]
  const std::string m = error({path("request.yaml"), "goal_constraints", "'slide'", "0.45", "[0, 0.3]"});
  std::cout << "[ message  ] " << m << "\n";
}

TEST_F(ArmBadInput, StartOutsideTheJointLimits) {
  edit("request.yaml", "position: [1.5707963267948966, 0, 0]", "position: [2.75, 0, 0]");  // shoulder: [-2.5, 2.5]
  const std::string m = error({path("request.yaml"), "start_state", "'shoulder'", "2.75"});
  std::cout << "[ message  ] " << m << "\n";
}

TEST_F(ArmBadInput, MissingCollisionMesh) {
  edit("two_link.urdf", "<sphere radius=\"0.03\"/>", "<mesh filename=\"package://two_link/meshes/tool.stl\"/>");
  // Tried: beside the URDF, then in the package's folder there.
  const std::string m = error({path("two_link.urdf"), "link 'tool'", "package://two_link/meshes/tool.stl", "tried",
                               (dir_ / "meshes" / "tool.stl").string(), (dir_ / "two_link" / "meshes" / "tool.stl").string()});
  std::cout << "[ message  ] " << m << "\n";
}

TEST_F(ArmBadInput, MissingRelativeCollisionMesh) {
  edit("two_link.urdf", "<sphere radius=\"0.03\"/>", "<mesh filename=\"meshes/tool.obj\"/>");
  const std::string m = error({path("two_link.urdf"), "link 'tool'", "meshes/tool.obj", "tried", (dir_ / "meshes" / "tool.obj").string()});
  std::cout << "[ message  ] " << m << "\n";
}

TEST_F(ArmBadInput, StartInCollisionWithAnObject) {
  // (0, 0, 0): link3 crosses the box (tests/data/arm/two_link/scene.yaml).
  edit("request.yaml", "position: [1.5707963267948966, 0, 0]", "position: [0, 0, 0]");
  const std::string m = error({path("request.yaml"), "start_state", "link 'link3'", "object 'obstacle'"});
  std::cout << "[ message  ] " << m << "\n";
}

TEST_F(ArmBadInput, GoalInSelfCollision) {
  // Wrist at pi folds link3 back over link1.
  edit("request.yaml", "position: 0.5", "position: 3.141592653589793");
  edit("request.yaml", "position: 0.2", "position: 0");
  const std::string m = error({path("request.yaml"), "goal_constraints", "links 'link1' and 'link3'"});
  std::cout << "[ message  ] " << m << "\n";
}

TEST_F(ArmBadInput, SceneObjectOfAnUnsupportedShape) {
  edit("scene.yaml", "type: box", "type: cone");
  const std::string m = error({path("scene.yaml"), "world.collision_objects[0].primitives[0].type", "cone"});
  std::cout << "[ message  ] " << m << "\n";
}

TEST_F(ArmBadInput, SceneObjectWithTooFewDimensions) {
  edit("scene.yaml", "dimensions: [0.1, 0.1, 0.1]", "dimensions: [0.1, 0.1]");
  const std::string m = error({path("scene.yaml"), "world.collision_objects[0].primitives[0].dimensions"});
  std::cout << "[ message  ] " << m << "\n";
}

}  // namespace
}  // namespace amp::world
