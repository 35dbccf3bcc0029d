#include "amp/roadmap/catalog/planner_registry.hpp"

#include <string>

#include <gtest/gtest.h>

#include "amp/roadmap/prm/prm.hpp"

namespace amp::roadmap {
namespace {

// The message of the ParameterError `f` throws ("" if none).
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const ParameterError& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(PlannerRegistry, BuiltinHasPrmWithDescribedParameters) {
  const PlannerRegistry& r = builtin_planners();
  EXPECT_TRUE(r.contains("prm"));
  const PlannerInfo& info = r.info("prm");
  std::vector<std::string> names;
  for (const core::ParamSpec& s : info.params) names.push_back(s.name);
  for (const char* n : {"k", "lazy", "smooth"}) EXPECT_NE(std::find(names.begin(), names.end(), n), names.end()) << n;
  EXPECT_EQ(info.params.front().default_value, core::ParamValue(10));
  EXPECT_FALSE(info.params.front().help.empty());
}

TEST(PlannerRegistry, MakesPrmWithTypedParameters) {
  const auto p = builtin_planners().make("prm", {{"k", 15}, {"lazy", "true"}, {"smooth", 1}});
  const auto* prm = dynamic_cast<const Prm*>(p.get());
  ASSERT_NE(prm, nullptr);
  EXPECT_EQ(prm->settings().k, 15);
  EXPECT_TRUE(prm->settings().lazy);
  EXPECT_TRUE(prm->settings().smooth);
  const auto q = builtin_planners().make("prm", {{"k", "7"}});  // numbers may come as text
  EXPECT_EQ(dynamic_cast<const Prm&>(*q).settings().k, 7);
  EXPECT_FALSE(dynamic_cast<const Prm&>(*q).settings().lazy);
}

TEST(PlannerRegistry, Errors) {
  const PlannerRegistry& r = builtin_planners();
  std::string m = error_of([&] { r.make("rrt", {}); });
  EXPECT_TRUE(contains(m, "unknown planner 'rrt'") && contains(m, "prm")) << m;
  m = error_of([&] { r.make("prm", {{"kk", 3}}); });
  EXPECT_TRUE(contains(m, "unknown parameter 'kk'") && contains(m, "k, lazy, smooth")) << m;
  m = error_of([&] { r.make("prm", {{"k", "ten"}}); });
  EXPECT_TRUE(contains(m, "'k'") && contains(m, "expected a number") && contains(m, "ten")) << m;
  m = error_of([&] { r.make("prm", {{"k", 0}}); });
  EXPECT_TRUE(contains(m, "outside [1, 1000]")) << m;
  m = error_of([&] { r.make("prm", {{"k", 2.5}}); });
  EXPECT_TRUE(contains(m, "expected an integer")) << m;
  m = error_of([&] { r.make("prm", {{"lazy", "maybe"}}); });
  EXPECT_TRUE(contains(m, "'lazy'") && contains(m, "true or false")) << m;
  m = error_of([&] { r.make("prm", {{"lazy", 2}}); });
  EXPECT_TRUE(contains(m, "true or false")) << m;
}

TEST(PlannerRegistry, CustomPlannersAndChoices) {
  PlannerRegistry r;
  register_prm(r);
  int made = 0;
  r.add({{"toy", "a test planner", {{"mode", core::ParamType::kChoice, "fast", 0, 0, {"fast", "slow"}, "speed"},
                                    {"gamma", core::ParamType::kReal, 0.5, 0.0, 1.0, {}, "mixing"}}}},
        [&made](const core::Params& p) {
          EXPECT_EQ(p.choice("mode"), "slow");
          EXPECT_DOUBLE_EQ(p.real("gamma"), 0.5);  // default filled in
          ++made;
          return std::make_unique<Prm>();
        });
  EXPECT_EQ(r.names(), (std::vector<std::string>{"prm", "toy"}));
  r.make("toy", {{"mode", "slow"}});
  EXPECT_EQ(made, 1);
  const std::string m = error_of([&] { r.make("toy", {{"mode", "medium"}}); });
  EXPECT_TRUE(contains(m, "'medium' is not one of fast, slow")) << m;
  EXPECT_THROW(r.add({{"toy", "", {}}}, nullptr), std::logic_error);
}

}  // namespace
}  // namespace amp::roadmap
