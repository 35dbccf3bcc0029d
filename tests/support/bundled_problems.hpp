#pragma once
// Shared by tests: a bundled problem (problems/<file>), loaded once per test binary and kept.
#include <map>
#include <string>

#include "amp/world/problem.hpp"
#include "support/source_tree.hpp"

namespace amp::test {

inline const world::Problem& bundled_problem(const std::string& file) {
  static std::map<std::string, world::Problem> loaded;
  auto it = loaded.find(file);
  if (it == loaded.end()) {
    std::string path = std::string(AMP_SOURCE_DIR) + "/problems/";
    path += file;  // appended in place: GCC 12 at -O1 warns falsely on a temporary's operator+
    it = loaded.emplace(file, world::load_problem(path)).first;
  }
  return it->second;
}

}  // namespace amp::test
