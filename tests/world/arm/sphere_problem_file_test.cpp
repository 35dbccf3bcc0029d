// An arm problem's collision model from its problem file (`collision:`, `spheres:`,
// docs/problem-format.md "Arms"), from the caller's ProblemOverrides over it (`amp plan --collision
// --spheres`), and from an experiment's `arm_folder` entry; and a problem whose seed collides only
// in the (larger) sphere model: every run of it reports kUnsolvable with the reason, without planning.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include "amp/bench/experiment.hpp"
#include "amp/core/error.hpp"
#include "amp/roadmap/run.hpp"
#include "amp/world/arm_environment.hpp"
#include "amp/world/arm_problem.hpp"
#include "amp/world/problem.hpp"
#include "support/sphere_test_cache.hpp"
#include "support/source_tree.hpp"

namespace amp::world {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

fs::path panda_dir() { return fs::path(AMP_SOURCE_DIR) / ".." / "shared" / "mbm" / "panda"; }

// A scratch folder per test binary run for the problem files written here. The sphere cache
// ($AMP_CACHE_DIR, which load_problem reads) is the tests' shared one, so nothing is written to the
// user's home; CollisionKeyChoosesTheModel points it at a fresh folder to see the entry written.
fs::path scratch() {
  static const fs::path dir = [] {
    const fs::path d = fs::temp_directory_path() / ("amp-sphere-problem-file-test-" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

class ScratchEnvironment : public ::testing::Environment {
 public:
  void SetUp() override { ::setenv("AMP_CACHE_DIR", test::shared_sphere_cache().c_str(), 1); }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(scratch(), ec);
  }
};
[[maybe_unused]] ::testing::Environment* const kScratch = ::testing::AddGlobalTestEnvironment(new ScratchEnvironment);

fs::path scene(const std::string& family, int n, const char* kind) {
  const std::string id = std::to_string(n);
  return panda_dir() / "problems" / family / (kind + std::string(4 - id.size(), '0') + id + ".yaml");
}

// A problem file naming the shared Panda and `family`'s problem `n`, plus `extra` lines.
fs::path write_problem(const std::string& name, const std::string& extra, const std::string& family = "box", int n = 1) {
  const fs::path file = scratch() / (name + ".yaml");
  std::ofstream(file) << "urdf: " << (panda_dir() / "panda.urdf").string() << "\nsrdf: "
                      << (panda_dir() / "panda.srdf").string() << "\nscene: " << scene(family, n, "scene").string()
                      << "\nrequest: " << scene(family, n, "request").string() << "\n"
                      << extra;
  return file;
}

bool sphere_checked(const Problem& p) { return dynamic_cast<const ArmEnvironment&>(*p.environment).sphere_checked(); }

fs::path spherized() { return panda_dir() / "panda_spherized.urdf"; }

// What load_problem throws for `file` (with `overrides`), or "" when it loads.
std::string file_error(const fs::path& file, const ProblemOverrides& overrides = {}) {
  try {
    load_problem(file, overrides);
  } catch (const FileError& e) {
    return e.what();
  }
  return "";
}

TEST(SphereProblemFile, CollisionKeyChoosesTheModel) {
  ::setenv("AMP_CACHE_DIR", (scratch() / "cache").c_str(), 1);
  EXPECT_TRUE(sphere_checked(load_problem(write_problem("spheres", "collision: spheres\n"))));
  EXPECT_FALSE(sphere_checked(load_problem(write_problem("meshes", "collision: meshes\n"))));
  EXPECT_FALSE(sphere_checked(load_problem(write_problem("default", ""))));
  EXPECT_TRUE(fs::is_directory(scratch() / "cache")) << "generated spheres are cached in $AMP_CACHE_DIR";
  ::setenv("AMP_CACHE_DIR", test::shared_sphere_cache().c_str(), 1);
}

TEST(SphereProblemFile, UnknownCollisionModelNamesTheField) {
  const std::string e = file_error(write_problem("bogus", "collision: bogus\n"));
  EXPECT_THAT(e, HasSubstr("bogus.yaml"));
  EXPECT_THAT(e, HasSubstr("collision"));
  EXPECT_THAT(e, HasSubstr("'bogus'"));
}

TEST(SphereProblemFile, SpheresKeyAloneImpliesSpheres) {
  const Problem p = load_problem(write_problem("spherized", "spheres: " + spherized().string() + "\n"));
  EXPECT_TRUE(sphere_checked(p));
}

TEST(SphereProblemFile, MissingSpheresFileNamesIt) {
  const std::string e = file_error(write_problem("no_spheres", "spheres: no_such_spheres.urdf\n"));
  EXPECT_THAT(e, HasSubstr("spheres"));
  EXPECT_THAT(e, HasSubstr("no_such_spheres.urdf"));
}

TEST(SphereProblemFile, MeshesWithASpheresFileIsAnError) {
  const std::string e = file_error(write_problem("both", "collision: meshes\nspheres: " + spherized().string() + "\n"));
  EXPECT_THAT(e, HasSubstr("both.yaml"));
  EXPECT_THAT(e, HasSubstr("spheres"));
}

TEST(SphereProblemFile, OverridesWinOverTheFile) {
  const fs::path meshes = write_problem("file_meshes", "collision: meshes\n");
  EXPECT_TRUE(sphere_checked(load_problem(meshes, ProblemOverrides{"spheres", {}, test::shared_sphere_cache()})));
  const fs::path spheres = write_problem("file_spheres", "collision: spheres\n");
  EXPECT_FALSE(sphere_checked(load_problem(spheres, ProblemOverrides{"meshes", {}, {}})));
  // A spherized URDF given by the caller implies spheres only with the collision model left to the
  // file; over `collision: meshes` the caller must say spheres too.
  EXPECT_TRUE(sphere_checked(load_problem(meshes, ProblemOverrides{"spheres", spherized(), {}})));
  EXPECT_THAT(file_error(meshes, ProblemOverrides{"", spherized(), {}}), HasSubstr("spheres"));
  EXPECT_THAT(file_error(meshes, ProblemOverrides{"cubes", {}, {}}), HasSubstr("'cubes'"));
}

TEST(SphereProblemFile, OverridesOnAPlanarProblemAreErrors) {
  const fs::path walls = fs::path(AMP_SOURCE_DIR) / "problems" / "walls.yaml";
  const fs::path cfg = fs::path(AMP_SOURCE_DIR) / "problems" / "ompl" / "gap_planar.cfg";
  for (const fs::path& file : {walls, cfg}) {
    EXPECT_THAT(file_error(file, ProblemOverrides{"spheres", {}, {}}), HasSubstr("arm problem")) << file;
    EXPECT_THAT(file_error(file, ProblemOverrides{"meshes", {}, {}}), HasSubstr("arm problem")) << file;
    EXPECT_THAT(file_error(file, ProblemOverrides{"", spherized(), {}}), HasSubstr("arm problem")) << file;
    // Only a cache folder (what `amp plan` always passes) is not a choice of model.
    EXPECT_EQ(file_error(file, ProblemOverrides{"", {}, test::shared_sphere_cache()}), "") << file;
  }
}

// The first shared Panda problem (box, table_pick, bookshelf_small, in order) whose seed is free on
// the meshes but collides in the generated sphere model; its files and the reason.
struct SphereOnlyCollision {
  std::string family;
  int number = 0;
  std::string reason;
};

SphereOnlyCollision find_sphere_only_collision() {
  const ArmDescription robot = load_arm_description(panda_dir() / "panda.urdf", panda_dir() / "panda.srdf", {},
                                                    ArmCollisionOptions{ArmCollision::kSpheres, {}, test::shared_sphere_cache()});
  for (const char* family : {"box", "table_pick", "bookshelf_small"}) {
    for (int n = 1; fs::is_regular_file(scene(family, n, "request")); ++n) {
      const Problem p = load_arm_problem(robot, scene(family, n, "scene"), scene(family, n, "request"));
      if (!p.unsolvable_because.empty()) return {family, n, p.unsolvable_because};
    }
  }
  return {};
}

TEST(SphereProblemFile, SeedCollidingOnlyInTheSphereModelMakesRunsUnsolvable) {
  const SphereOnlyCollision found = find_sphere_only_collision();
  ASSERT_FALSE(found.reason.empty()) << "no shared Panda problem collides only in the sphere model";
  EXPECT_THAT(found.reason, HasSubstr("collides in the sphere model"));
  RecordProperty("found", found.family + " " + std::to_string(found.number) + ": " + found.reason);
  const Problem meshes = load_problem(write_problem("found_meshes", "", found.family, found.number));
  EXPECT_TRUE(meshes.unsolvable_because.empty());

  const Problem p = load_problem(write_problem("found_spheres", "collision: spheres\n", found.family, found.number));
  ASSERT_EQ(p.unsolvable_because, found.reason) << found.family << " " << found.number;
  for (const char* planner : {"rrt-connect", "prm"}) {
    const roadmap::RunOutcome run = roadmap::execute_run(p, planner, {}, 1, 5.0, std::nullopt);
    EXPECT_EQ(run.record.status, core::PlanStatus::kUnsolvable) << planner;
    EXPECT_EQ(run.record.message, found.reason) << planner;
    EXPECT_TRUE(run.path.empty()) << planner;
    EXPECT_EQ(run.record.cd_calls(), 0u) << planner << ": nothing is planned";
  }
}

// ---- an experiment's arm_folder entry takes the same keys

fs::path write_experiment(const std::string& name, const std::string& extra) {
  const fs::path file = scratch() / (name + ".yaml");
  std::ofstream(file) << "name: " << name << "\nruns: 1\ntime_limit: 1\nproblems:\n  - arm_folder: "
                      << (panda_dir() / "problems" / "box").string() << "\n    urdf: " << (panda_dir() / "panda.urdf").string()
                      << "\n    srdf: " << (panda_dir() / "panda.srdf").string() << "\n    count: 2\n"
                      << extra << "planners:\n  - rrt-connect\n";
  return file;
}

TEST(SphereExperimentKeys, ArmFolderTakesTheCollisionModel) {
  const bench::Experiment spheres = bench::load_experiment(write_experiment("spheres", "    collision: spheres\n"));
  ASSERT_EQ(spheres.problems.size(), 2u);
  for (const bench::ExperimentProblem& ep : spheres.problems) EXPECT_TRUE(sphere_checked(*ep.problem)) << ep.label;
  const bench::Experiment meshes = bench::load_experiment(write_experiment("meshes", ""));
  ASSERT_EQ(meshes.problems.size(), 2u);
  for (const bench::ExperimentProblem& ep : meshes.problems) EXPECT_FALSE(sphere_checked(*ep.problem)) << ep.label;
  const bench::Experiment spherized_only =
      bench::load_experiment(write_experiment("spherized", "    spheres: " + spherized().string() + "\n"));
  for (const bench::ExperimentProblem& ep : spherized_only.problems) EXPECT_TRUE(sphere_checked(*ep.problem)) << ep.label;
}

TEST(SphereExperimentKeys, BadCollisionKeysAreFileErrors) {
  try {
    bench::load_experiment(write_experiment("bogus", "    collision: bogus\n"));
    ADD_FAILURE() << "collision: bogus was accepted";
  } catch (const FileError& e) {
    EXPECT_THAT(e.what(), HasSubstr("collision"));
  }
  try {
    bench::load_experiment(write_experiment("both", "    collision: meshes\n    spheres: " + spherized().string() + "\n"));
    ADD_FAILURE() << "collision: meshes with spheres: was accepted";
  } catch (const FileError& e) {
    EXPECT_THAT(e.what(), HasSubstr("spheres"));
  }
}

}  // namespace
}  // namespace amp::world
