// SettingsSchema: a Settings struct's parameters written once serve the catalog (specs with the
// struct's defaults), the factory (read from checked Params) and validate() (the same checks).
#include "amp/core/settings_schema.hpp"

#include <gtest/gtest.h>

#include <string>

#include "amp/core/error.hpp"

namespace amp::core {
namespace {

enum class Mode { kFast, kSlow };

struct Inner {
  double gain = 0.5;
  static const SettingsSchema<Inner>& schema() {
    static const SettingsSchema<Inner> s("inner", {real_field<Inner>("gain", &Inner::gain, 0, 1, "a gain")});
    return s;
  }
};

struct Outer {
  int k = 10;
  bool lazy = false;
  std::string name = "a";
  Mode mode = Mode::kSlow;
  Inner inner;
  static const SettingsSchema<Outer>& schema() {
    static const SettingsSchema<Outer> s("outer", [] {
      std::vector<SettingsField<Outer>> f{
          integer_field<Outer>("k", &Outer::k, 1, 100, "neighbours"),
          bool_field<Outer>("lazy", &Outer::lazy, "lazy"),
          choice_field<Outer>("name", &Outer::name, {"a", "b"}, "a name"),
          enum_field<Outer>("mode", &Outer::mode,
                            std::vector<std::pair<std::string, Mode>>{{"fast", Mode::kFast}, {"slow", Mode::kSlow}},
                            "speed")};
      for (auto& g : nested_fields<Outer>(Inner::schema(), &Outer::inner)) f.push_back(std::move(g));
      return f;
    }());
    return s;
  }
};

TEST(SettingsSchema, SpecsCarryTheStructsDefaultsInOrder) {
  const std::vector<ParamSpec>& specs = Outer::schema().specs();
  ASSERT_EQ(specs.size(), 5u);
  EXPECT_EQ(specs[0].name, "k");
  EXPECT_EQ(specs[0].default_value, ParamValue(10));
  EXPECT_EQ(specs[0].type, ParamType::kInteger);
  EXPECT_EQ(specs[1].default_value, ParamValue(0));
  EXPECT_EQ(specs[2].default_value, ParamValue("a"));
  EXPECT_EQ(specs[3].default_value, ParamValue("slow"));
  EXPECT_EQ(specs[3].choices, (std::vector<std::string>{"fast", "slow"}));
  EXPECT_EQ(specs[4].name, "gain");
  EXPECT_EQ(specs[4].default_value, ParamValue(0.5));
}

TEST(SettingsSchema, ReadsEveryFieldFromCheckedParams) {
  const Params p("outer", Outer::schema().specs(),
                 {{"k", 7}, {"lazy", "true"}, {"name", "b"}, {"mode", "fast"}, {"gain", "0.25"}});
  const Outer o = Outer::schema().read(p);
  EXPECT_EQ(o.k, 7);
  EXPECT_TRUE(o.lazy);
  EXPECT_EQ(o.name, "b");
  EXPECT_EQ(o.mode, Mode::kFast);
  EXPECT_DOUBLE_EQ(o.inner.gain, 0.25);
  const Outer d = Outer::schema().read(Params("outer", Outer::schema().specs(), {}));  // all defaults
  EXPECT_EQ(d.k, 10);
  EXPECT_EQ(d.mode, Mode::kSlow);
}

TEST(SettingsSchema, ValidateChecksAStructBuiltInCodeAsUserInput) {
  Outer o;
  EXPECT_NO_THROW(Outer::schema().validate(o));
  o.k = 0;
  try {
    Outer::schema().validate(o);
    ADD_FAILURE() << "k = 0 accepted";
  } catch (const ParameterError& e) {
    EXPECT_EQ(std::string(e.what()), "outer: parameter 'k': 0 is outside [1, 100]");
  }
  o.k = 5;
  o.inner.gain = 2.0;
  EXPECT_THROW(Outer::schema().validate(o), ParameterError);
  o.inner.gain = 0.5;
  o.name = "c";
  EXPECT_THROW(Outer::schema().validate(o), ParameterError);
  o.name = "a";
  o.mode = static_cast<Mode>(7);  // not a listed value
  EXPECT_THROW(Outer::schema().validate(o), ParameterError);
}

}  // namespace
}  // namespace amp::core
