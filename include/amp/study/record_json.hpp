#pragma once
#include <optional>

#include <nlohmann/json.hpp>

#include "amp/core/parameters.hpp"

// The pieces every study's record.json is written with, so that the three studies write a value
// the same way.
namespace amp::study {

// A parameter's value: integers as integers (the schema stores every number as a double).
nlohmann::ordered_json param_json(const core::ParamValue& v);
// A number, null when not finite (JSON has no infinity).
nlohmann::ordered_json finite_or_null(double x);
// A statistic that may not exist (the median of no sample): null when it does not.
nlohmann::ordered_json optional_json(const std::optional<double>& x);

}  // namespace amp::study
