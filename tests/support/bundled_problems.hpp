#pragma once
// Shared by tests: a bundled problem (problems/<file>), loaded once per test binary and kept.
#include <map>
#include <string>

#include "amp/world/problem.hpp"

namespace amp::test {

inline const world::Problem& bundled_problem(const std::string& file) {
  static std::map<std::string, world::Problem> loaded;
  auto it = loaded.find(file);
  if (it == loaded.end()) {
    it = loaded.emplace(file, world::load_problem(std::string(AMP_SOURCE_DIR) + "/problems/" + file)).first;
  }
  return it->second;
}

}  // namespace amp::test
