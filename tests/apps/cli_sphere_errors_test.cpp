// `amp plan` choosing an arm's collision model (`--collision meshes|spheres`, `--spheres FILE`,
// docs/arms.md "Sphere model"): bad choices end with exit code 1 and one stderr line naming the
// option, file or link; good ones plan the shared Panda's box problem. Generated spheres go to a
// cache the tests share in the build tree ($AMP_CACHE_DIR, support/sphere_test_cache.hpp), never the user's.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/cli_errors_fixture.hpp"
#include "support/sphere_test_cache.hpp"
#include "support/source_tree.hpp"

namespace {

namespace fs = std::filesystem;
using namespace amp::test;  // CliErrors, run helpers, kData, kExit*
using ::testing::AnyOf;
using ::testing::HasSubstr;
using ::testing::StartsWith;

const fs::path kPanda = fs::path(AMP_SOURCE_DIR) / ".." / "shared" / "mbm" / "panda";

std::string quoted(const fs::path& p) {
  std::string q = "'";
  q += p.string();
  q += '\'';
  return q;
}

// The four MoveIt files of the shared Panda's box problem 0001, as `amp plan` flags.
std::string panda_box_flags() {
  return "--urdf " + quoted(kPanda / "panda.urdf") + " --srdf " + quoted(kPanda / "panda.srdf") + " --scene " +
         quoted(kPanda / "problems" / "box" / "scene0001.yaml") + " --request " +
         quoted(kPanda / "problems" / "box" / "request0001.yaml");
}

class CliSpheres : public CliErrors {
 protected:
  void SetUp() override {
    CliErrors::SetUp();
    // Inherited by the amp that run() starts: the tests' shared cache, never the user's; the test
    // that sees the entry written points it at its own folder.
    ::setenv("AMP_CACHE_DIR", amp::test::shared_sphere_cache().c_str(), 1);
  }
  void TearDown() override {
    ::unsetenv("AMP_CACHE_DIR");
    CliErrors::TearDown();
  }
};

// ---- bad choices: exit code 1, one line

TEST_F(CliSpheres, UnknownCollisionModelIsRejected) {
  expect_input_error(plan(panda_box_flags(), "--collision cubes"), {"--collision", "cubes"});
}

TEST_F(CliSpheres, MissingSpheresFileIsNamed) {
  expect_input_error(plan(panda_box_flags(), "--spheres /nonexistent.urdf"), {"/nonexistent.urdf"});
}

// A spherized URDF with a link the robot lacks (the left finger renamed, with its joint's reference).
TEST_F(CliSpheres, SpheresForALinkTheRobotLacksNameTheLink) {
  std::string text = read_file(kPanda / "panda_spherized.urdf");
  ASSERT_THAT(text, HasSubstr("<link name=\"panda_leftfinger\">"));
  int renamed = 0;
  for (std::size_t at = text.find("panda_leftfinger"); at != std::string::npos; at = text.find("panda_leftfinger", at)) {
    text.replace(at, 16, "panda_thumb");
    ++renamed;
  }
  ASSERT_EQ(renamed, 2);  // the link and its joint's child
  std::ofstream(dir_ / "thumb_spherized.urdf") << text;
  const RunResult r = plan(panda_box_flags(), "--spheres thumb_spherized.urdf");
  expect_input_error(r, {"thumb_spherized.urdf", "panda_thumb"});
}

TEST_F(CliSpheres, SpheresOnAPlanarProblemFile) {
  expect_input_error(plan(data("sealed.yaml"), "--collision spheres"), {"sealed.yaml", "arm"});
  expect_input_error(plan(data("sealed.yaml"), "--spheres " + quoted(kPanda / "panda_spherized.urdf")),
                     {"sealed.yaml", "arm"});
}

TEST_F(CliSpheres, MeshesWithASpheresFile) {
  expect_input_error(plan(panda_box_flags(), "--collision meshes --spheres " + quoted(kPanda / "panda_spherized.urdf")),
                     {"--spheres", "--collision spheres"});
}

// The same through a problem file naming the four files.
TEST_F(CliSpheres, MeshesWithASpheresFileOverAProblemFile) {
  std::ofstream(dir_ / "panda.yaml") << "urdf: " << (kPanda / "panda.urdf").string() << "\nsrdf: "
                                     << (kPanda / "panda.srdf").string() << "\nscene: "
                                     << (kPanda / "problems" / "box" / "scene0001.yaml").string() << "\nrequest: "
                                     << (kPanda / "problems" / "box" / "request0001.yaml").string() << "\n";
  expect_input_error(plan("panda.yaml", "--collision meshes --spheres " + quoted(kPanda / "panda_spherized.urdf")),
                     {"panda.yaml", "spheres"});
}

// ---- good choices plan

TEST_F(CliSpheres, GeneratedSpheresSolveTheBoxProblem) {
  ::setenv("AMP_CACHE_DIR", (dir_ / "cache").c_str(), 1);
  const RunResult r = run("plan " + panda_box_flags() + " --collision spheres --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("status"), "solved");
  EXPECT_GE(j.at("path_states").get<int>(), 2);
  EXPECT_TRUE(fs::is_directory(dir_ / "cache")) << "the generated spheres are cached in $AMP_CACHE_DIR";
}

// VAMP's spherized Panda, grown to cover the meshes: solved, or unsolvable because a seed collides in
// the larger sphere model (exit code 2, the reason in the record).
TEST_F(CliSpheres, SpherizedUrdfPlansOrSaysWhyNot) {
  const RunResult r = run("plan " + panda_box_flags() + " --spheres " + quoted(kPanda / "panda_spherized.urdf") + " --json");
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const std::string status = j.at("status");
  ASSERT_THAT(status, AnyOf("solved", "unsolvable")) << r.err;
  if (status == "solved") {
    EXPECT_EQ(r.exit_code, 0) << r.err;
  } else {
    EXPECT_EQ(r.exit_code, kExitNotSolved) << r.err;
    EXPECT_THAT(j.at("message").get<std::string>(), HasSubstr("sphere model"));
    const std::vector<std::string> lines = lines_of(r.err);
    ASSERT_EQ(lines.size(), 1u) << r.err;
    EXPECT_THAT(lines[0], StartsWith("amp: no solution"));
  }
}

}  // namespace
