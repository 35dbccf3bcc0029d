#include "amp/roadmap/prm/sampler_prm_settings.hpp"

#include <string>

#include <gtest/gtest.h>

#include "amp/core/error.hpp"
#include "amp/roadmap/catalog/planner_registry.hpp"

namespace amp::roadmap {
namespace {

const core::ParamSpec& spec(const std::vector<core::ParamSpec>& specs, const std::string& name) {
  for (const core::ParamSpec& s : specs) {
    if (s.name == name) return s;
  }
  throw std::logic_error("no parameter " + name);
}

// The catalog lists exactly the schema's parameters, and k is PRM's own.
TEST(SamplerPrmSettings, CatalogListsTheSchemas) {
  const PlannerRegistry& registry = builtin_planners();
  const auto names = [](const std::vector<core::ParamSpec>& specs) {
    std::string out;
    for (const core::ParamSpec& s : specs) out += s.name + " ";
    return out;
  };
  EXPECT_EQ(names(registry.info("gaussian-prm").params), "k d d_scale max_attempts ");
  EXPECT_EQ(names(registry.info("obprm").params), "k max_attempts max_steps ");
  EXPECT_EQ(names(registry.info("bridge-prm").params), "k d d_scale max_attempts uniform_mix ");
  const core::ParamSpec& prm_k = spec(PrmSettings::schema().specs(), "k");
  const core::ParamSpec& k = spec(BridgePrmSettings::schema().specs(), "k");
  EXPECT_EQ(k.min, prm_k.min);
  EXPECT_EQ(k.max, prm_k.max);
  EXPECT_EQ(k.help, prm_k.help);
  EXPECT_EQ(spec(GaussianPrmSettings::schema().specs(), "d_scale").default_value, core::ParamValue(1.0));
  EXPECT_EQ(spec(BridgePrmSettings::schema().specs(), "d_scale").default_value, core::ParamValue(2.0));
}

// validate() on a struct built in code applies the very ranges the catalog applies to user input.
TEST(SamplerPrmSettings, ValidateUsesTheCatalogRanges) {
  GaussianPrmSettings g;
  EXPECT_NO_THROW(g.validate());
  g.max_attempts = 0;
  EXPECT_THROW(g.validate(), ParameterError);
  ObprmSettings o;
  o.max_steps = 0;
  EXPECT_THROW(o.validate(), ParameterError);
  BridgePrmSettings b;
  b.uniform_mix = 1.5;
  EXPECT_THROW(b.validate(), ParameterError);
  b.uniform_mix = 1.0;
  b.k = 0;
  EXPECT_THROW(b.validate(), ParameterError);

  const PlannerRegistry& registry = builtin_planners();
  EXPECT_THROW(registry.make("bridge-prm", {{"uniform_mix", 1.5}}), ParameterError);
  EXPECT_THROW(registry.make("obprm", {{"max_steps", 0}}), ParameterError);
  EXPECT_NO_THROW(registry.make("gaussian-prm", {{"d", 0.5}, {"max_attempts", 10}}));
}

}  // namespace
}  // namespace amp::roadmap
