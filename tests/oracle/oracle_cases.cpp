#include "oracle_cases.hpp"

#include <algorithm>
#include <cctype>

namespace amp::oracle {

namespace fs = std::filesystem;

namespace {

std::string test_name(const fs::path& file) {
  std::string n = file.stem().string();
  for (char& c : n) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return n;
}

}  // namespace

std::vector<CfgCase> cfg_cases() {
  std::vector<CfgCase> cases;
  for (const auto& entry : fs::recursive_directory_iterator(fs::path(AMP_SOURCE_DIR) / "problems")) {
    if (entry.is_regular_file() && entry.path().extension() == ".cfg") {
      cases.push_back({test_name(entry.path()), entry.path(), false});
    }
  }
  for (const char* stem : {"BugTrap_planar", "Maze_planar", "Twistycool"}) {
    const fs::path file = fs::path(AMP_OMPLAPP_DIR) / (std::string(stem) + ".cfg");
    cases.push_back({test_name(file), file, true});
  }
  std::sort(cases.begin(), cases.end(), [](const CfgCase& a, const CfgCase& b) { return a.name < b.name; });
  return cases;
}

fs::path reference_path_of(const fs::path& cfg) {
  fs::path p = cfg;
  p.replace_extension(".path");
  return fs::is_regular_file(p) ? p : fs::path();
}

}  // namespace amp::oracle
