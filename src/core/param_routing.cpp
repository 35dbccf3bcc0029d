#include "amp/core/param_routing.hpp"

#include <algorithm>

#include "amp/core/error.hpp"

namespace amp::core {

bool declares(const std::vector<ParamSpec>& specs, const std::string& name) {
  return std::any_of(specs.begin(), specs.end(), [&name](const ParamSpec& s) { return s.name == name; });
}

namespace {

std::string valid_names(std::initializer_list<const std::vector<ParamSpec>*> schemas) {
  std::vector<std::string> names;
  for (const std::vector<ParamSpec>* specs : schemas) {
    for (const ParamSpec& s : *specs) {
      if (std::find(names.begin(), names.end(), s.name) == names.end()) names.push_back(s.name);
    }
  }
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

}  // namespace

std::vector<ParamMap> route_params(const ParamMap& given, std::initializer_list<const std::vector<ParamSpec>*> schemas) {
  std::vector<ParamMap> out(schemas.size());
  for (const auto& [name, value] : given) {
    bool taken = false;
    std::size_t i = 0;
    for (const std::vector<ParamSpec>* specs : schemas) {
      if (declares(*specs, name)) {
        out[i].insert_or_assign(name, value);
        taken = true;
      }
      ++i;
    }
    if (!taken) throw ParameterError("unknown parameter '" + name + "' (valid: " + valid_names(schemas) + ")");
  }
  return out;
}

}  // namespace amp::core
