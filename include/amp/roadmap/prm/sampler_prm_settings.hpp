#pragma once
#include "amp/core/settings_schema.hpp"
#include "amp/roadmap/prm/prm.hpp"

namespace amp::roadmap {

// The PRMs that differ from `prm` only by their sampler (gaussian-prm, obprm, bridge-prm). Each
// parameter is written once, in the schema; the catalog lists and reads it, validate() checks a
// struct built in code. k is PRM's own field, with PRM's range.

// d = 0 ("auto") stands for d_scale times the robot's smallest diameter (sampler_distance()).
struct GaussianPrmSettings {
  int k = 10;
  double d = 0.0;
  double d_scale = 1.0;
  int max_attempts = 100;
  static const core::SettingsSchema<GaussianPrmSettings>& schema();
  void validate() const { schema().validate(*this); }  // throws ParameterError
};

struct ObprmSettings {
  int k = 10;
  int max_attempts = 100;
  int max_steps = 1000;
  static const core::SettingsSchema<ObprmSettings>& schema();
  void validate() const { schema().validate(*this); }  // throws ParameterError
};

struct BridgePrmSettings {
  int k = 10;
  double d = 0.0;
  double d_scale = 2.0;  // Hsu et al.: bridges about twice the robot's size
  int max_attempts = 100;
  double uniform_mix = 0.0;
  static const core::SettingsSchema<BridgePrmSettings>& schema();
  void validate() const { schema().validate(*this); }  // throws ParameterError
};

}  // namespace amp::roadmap
