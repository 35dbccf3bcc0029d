#include "amp/stats/group_test.hpp"

#include <cmath>
#include <string>

#include "amp/core/error.hpp"

namespace amp::stats {

std::string_view to_string(TestStatus s) {
  switch (s) {
    case TestStatus::kOk: return "ok";
    case TestStatus::kZeroVariance: return "zero variance";
    case TestStatus::kTooFewObservations: return "too few observations";
  }
  return "unknown";
}

void require_groups(const Groups& groups, std::string_view test) {
  const std::string name(test);
  if (groups.size() < 2) {
    throw ParameterError(name + ": groups: need at least 2 groups, got " + std::to_string(groups.size()));
  }
  for (std::size_t g = 0; g < groups.size(); ++g) {
    if (groups[g].empty()) {
      throw ParameterError(name + ": groups[" + std::to_string(g) + "]: group is empty");
    }
    for (std::size_t i = 0; i < groups[g].size(); ++i) {
      if (!std::isfinite(groups[g][i])) {
        throw ParameterError(name + ": groups[" + std::to_string(g) + "][" + std::to_string(i) +
                             "]: value is not finite: " + std::to_string(groups[g][i]));
      }
    }
  }
}

std::size_t total_count(const Groups& groups) {
  std::size_t n = 0;
  for (const auto& g : groups) n += g.size();
  return n;
}

}  // namespace amp::stats
