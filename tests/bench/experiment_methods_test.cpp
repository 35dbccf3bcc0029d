// experiment.cpp with methods from both catalogs and `cost:`: what an experiment file may name, and
// the one-line errors (file and field) for what it may not.
#include "amp/bench/experiment.hpp"

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "amp/bench/method_runner.hpp"
#include "amp/core/error.hpp"
#include "amp/nav/navigator_catalog.hpp"
#include "amp/roadmap/catalog/planner_registry.hpp"
#include "support/source_tree.hpp"

namespace amp::bench {
namespace {

namespace fs = std::filesystem;

class ExperimentMethodsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("amp-experiment-methods-" + std::to_string(::getpid()) + "-" +
                                         ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(root_);
    fs::create_directories(root_);
  }
  void TearDown() override { fs::remove_all(root_); }

  // An experiment on walls.yaml with `extra` lines added at the top level.
  fs::path write(const std::string& file, const std::string& extra, const std::string& planners = "[prm]") {
    const fs::path walls = fs::path(AMP_SOURCE_DIR) / "problems" / "walls.yaml";
    std::ofstream(root_ / file) << "name: m\nseed: 3\nruns: 2\n" << extra << "problems: [" << walls.string()
                                << "]\nplanners: " << planners << "\n";
    return root_ / file;
  }

  // The message of the error load_experiment throws, or "" when it loads.
  static std::string error_of(const fs::path& file) {
    try {
      load_experiment(file);
    } catch (const FileError& e) {
      return e.what();
    }
    return "";
  }

  fs::path root_;
};

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST_F(ExperimentMethodsTest, CostDefaultsToCdCallsAndKeepsTheFingerprint) {
  const Experiment plain = load_experiment(write("plain.yaml", ""));
  const Experiment explicit_default = load_experiment(write("default.yaml", "cost: cd_calls\n"));
  const Experiment by_length = load_experiment(write("length.yaml", "cost: path_length\n"));
  const Experiment by_extra = load_experiment(write("extra.yaml", "cost: replans\n"));
  EXPECT_EQ(plain.cost, "cd_calls");
  EXPECT_EQ(by_length.cost, "path_length");
  EXPECT_EQ(by_extra.cost, "replans");
  EXPECT_EQ(plain.fingerprint, explicit_default.fingerprint) << "old fingerprints stay valid";
  EXPECT_NE(plain.fingerprint, by_length.fingerprint) << "the cost decides the tests: shards must agree on it";
  EXPECT_NE(by_length.fingerprint, by_extra.fingerprint);
  EXPECT_EQ(plain.planners[0].kind, MethodKind::kPlanner);
}

TEST_F(ExperimentMethodsTest, ACostThatIsNoMetricIsAOneLineErrorNamingFileAndField) {
  for (const std::string bad : {"status", "seed", "\"two words\"", "param.k"}) {
    const fs::path f = write("bad.yaml", "cost: " + bad + "\n");
    const std::string m = error_of(f);
    EXPECT_TRUE(has(m, f.string()) && has(m, "cost")) << bad << ": " << m;
    EXPECT_FALSE(has(m, "\n")) << m;
  }
}

TEST_F(ExperimentMethodsTest, AnUnknownMethodNamesBothCatalogs) {
  const fs::path f = write("unknown.yaml", "", "[{name: x, planner: nope}]");
  const std::string m = error_of(f);
  EXPECT_TRUE(has(m, f.string())) << m;
  EXPECT_TRUE(has(m, "planners[0].planner")) << m;
  EXPECT_TRUE(has(m, "unknown planner or navigation method 'nope'")) << m;
  EXPECT_TRUE(has(m, "planners: ") && has(m, "prm") && has(m, "navigation methods: ")) << m;
  EXPECT_FALSE(has(m, "\n")) << m;
  const std::string scalar = error_of(write("unknown2.yaml", "", "[nope]"));
  EXPECT_TRUE(has(scalar, "planners[0]") && has(scalar, "'nope'")) << scalar;
  EXPECT_THROW(method_kind("nope"), ParameterError);
  EXPECT_EQ(method_kind("prm"), MethodKind::kPlanner);
}

// An experiment names a method by name alone, so no name may be in both catalogs.
TEST(MethodCatalogs, NoNameIsBothAPlannerAndANavigationMethod) {
  for (const std::string& name : nav::builtin_navigators().names()) {
    EXPECT_FALSE(roadmap::builtin_planners().contains(name)) << name;
    EXPECT_EQ(method_kind(name), MethodKind::kNavigator) << name;
  }
}

}  // namespace
}  // namespace amp::bench
