#include "amp/roadmap/prm/sampler_prm_settings.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace amp::roadmap {

namespace {

constexpr double kMaxAttempts = 1e6;  // tries per sample, and OBPRM's steps per ray
constexpr double kMaxDistance = 1e12;
constexpr double kMaxScale = 1e3;

// PRM's own k: its name, range and help as `prm` declares them.
template <class S>
core::SettingsField<S> k_field() {
  for (const core::ParamSpec& k : PrmSettings::schema().specs()) {
    if (k.name == "k") return core::integer_field<S>(k.name, &S::k, k.min, k.max, k.help);
  }
  throw std::logic_error("prm declares no k");
}
template <class S>
core::SettingsField<S> d_field() {
  return core::real_field<S>("d", &S::d, 0, kMaxDistance,
                             "sampler distance (space metric); 0 = d_scale * robot min diameter");
}
template <class S>
core::SettingsField<S> d_scale_field() {
  return core::real_field<S>("d_scale", &S::d_scale, 1e-6, kMaxScale, "d in robot min diameters when d = 0");
}
template <class S>
core::SettingsField<S> attempts_field() {
  return core::integer_field<S>("max_attempts", &S::max_attempts, 1, kMaxAttempts, "tries before a sample is given up");
}

}  // namespace

const core::SettingsSchema<GaussianPrmSettings>& GaussianPrmSettings::schema() {
  using S = GaussianPrmSettings;
  static const core::SettingsSchema<S> schema("gaussian-prm",
                                              {k_field<S>(), d_field<S>(), d_scale_field<S>(), attempts_field<S>()});
  return schema;
}

const core::SettingsSchema<ObprmSettings>& ObprmSettings::schema() {
  using S = ObprmSettings;
  static const core::SettingsSchema<S> schema(
      "obprm", {k_field<S>(), attempts_field<S>(),
                core::integer_field<S>("max_steps", &S::max_steps, 1, kMaxAttempts, "resolution steps along one ray")});
  return schema;
}

const core::SettingsSchema<BridgePrmSettings>& BridgePrmSettings::schema() {
  using S = BridgePrmSettings;
  static const core::SettingsSchema<S> schema(
      "bridge-prm", {k_field<S>(), d_field<S>(), d_scale_field<S>(), attempts_field<S>(),
                     core::real_field<S>("uniform_mix", &S::uniform_mix, 0, 1,
                                         "probability of a plain uniform sample instead")});
  return schema;
}

}  // namespace amp::roadmap
