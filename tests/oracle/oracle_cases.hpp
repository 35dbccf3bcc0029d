#pragma once
// The `.cfg` problems the oracle compares AMP against: every one under problems/ and OMPL.app's
// reference problems in AMP_OMPLAPP_DIR (test data kept outside the repository).
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace amp::oracle {

struct CfgCase {
  std::string name;            // a GoogleTest-safe name: the file's stem, non-alphanumerics as '_'
  std::filesystem::path file;  // may not exist for a reference problem: the test then skips
  bool reference = false;      // one of OMPL.app's own problems (AMP_OMPLAPP_DIR)
};

// GoogleTest prints a parameter with this (its bytes otherwise).
inline void PrintTo(const CfgCase& c, std::ostream* os) { *os << c.file.string(); }

// Sorted by name; the three reference problems are always listed, so that a machine without
// AMP_OMPLAPP_DIR shows them skipped rather than silently absent.
std::vector<CfgCase> cfg_cases();

// OMPL.app's reference solution `<stem>.path` beside the cfg, or an empty path.
std::filesystem::path reference_path_of(const std::filesystem::path& cfg);

}  // namespace amp::oracle
