#pragma once
#include <initializer_list>
#include <string>
#include <vector>

#include "amp/core/parameters.hpp"

namespace amp::core {

// The one settings reader for parameters spread over several schemas (a study's settings, the two
// methods of Table 2): commands (`--param`), Python (`params=`) and `amp bench` rows route what the
// user gave through it. Each given parameter goes to every schema that declares it (SINS's
// `max_cases` is both the cases' and sins-plus's); one no schema declares throws ParameterError
// "unknown parameter 'x' (valid: a, b, ...)", the valid names in the schemas' order, each once.
std::vector<ParamMap> route_params(const ParamMap& given, std::initializer_list<const std::vector<ParamSpec>*> schemas);

// Whether `specs` declares `name`.
bool declares(const std::vector<ParamSpec>& specs, const std::string& name);

}  // namespace amp::core
