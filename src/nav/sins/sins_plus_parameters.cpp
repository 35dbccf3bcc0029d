#include "amp/nav/sins/sins_plus_parameters.hpp"

#include <algorithm>

namespace amp::nav {

namespace {
// `initial` as the first case's outputs, checked first, so that a parameter outside its range is
// named by its schema name rather than reported as an output outside [0, 1].
learn::CaseOutputs checked_outputs(const SchemaParameters& initial) {
  initial.validate();
  return initial.normalised();
}
}  // namespace

SplittingCaseParameters::SplittingCaseParameters(learn::SplittingCaseSettings settings, SchemaParameters initial)
    : library_(settings, checked_outputs(initial)) {}

SchemaParameters SplittingCaseParameters::begin_world(core::Rng& rng) {
  library_.begin_episode();
  return SchemaParameters::from_normalised(library_.choose(kStartInputs, rng));
}

SchemaParameters SplittingCaseParameters::end_interval(const learn::CaseInputs& inputs, core::Rng& rng) {
  library_.reward(std::clamp(2.0 * inputs[3] - 1.0, -1.0, 1.0));
  return SchemaParameters::from_normalised(library_.choose(inputs, rng));
}

void SplittingCaseParameters::end_world(bool solved, double /*steps_fraction*/) {
  library_.end_episode(solved ? 1.0 : learn::SplittingCaseLibrary::kNoTerminal);
}

}  // namespace amp::nav
