#pragma once
#include <atomic>
#include <cstdint>
#include <string>

#include "amp/core/parameters.hpp"
#include "amp/nav/navigator.hpp"
#include "amp/world/problem.hpp"

namespace amp::study {

// One run of a navigation method of the built-in catalog, the one path for `amp bench`'s navigation
// rows, Python's amp.navigate and the runs of Table 2 (navigate_study.hpp): nav::execute_navigation
// with the problem, the method's parameters, Rng(seed) and the limits. Throws ParameterError for a
// bad name, parameter or problem; a run that fails otherwise has status kError.
nav::NavigationOutcome run_navigation(const world::Problem& problem, const std::string& method,
                                      const core::ParamMap& params, std::uint64_t seed, double time_limit_s,
                                      const std::atomic<bool>* cancel = nullptr);

}  // namespace amp::study
