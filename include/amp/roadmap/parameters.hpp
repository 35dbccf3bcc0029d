#pragma once
// Planner parameters are core's method parameters (core/parameters.hpp), shared with the
// navigation methods; the roadmap module names them as its own.
#include "amp/core/parameters.hpp"

namespace amp::roadmap {

using core::ParamMap;
using core::Params;
using core::ParamSpec;
using core::ParamType;
using core::ParamValue;

}  // namespace amp::roadmap
