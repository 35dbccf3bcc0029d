#include "amp/core/edge_check_mode.hpp"

#include "amp/core/error.hpp"

namespace amp::core {

EdgeCheckMode parse_edge_check_mode(const std::string& text) {
  if (text == "discrete") return EdgeCheckMode::kDiscrete;
  if (text == "certified") return EdgeCheckMode::kCertified;
  throw ParameterError("expected 'certified' or 'discrete', got '" + text + "'");
}

const char* to_string(EdgeCheckMode mode) { return mode == EdgeCheckMode::kCertified ? "certified" : "discrete"; }

}  // namespace amp::core
