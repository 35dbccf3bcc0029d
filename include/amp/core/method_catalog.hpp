#pragma once
// Methods by name: roadmap planners today, navigation methods beside them. A method is registered
// with what `amp bench --list` prints about it and a factory; user parameters are checked against
// its ParamSpecs before the factory runs, so factories read typed, in-range values.
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "amp/core/error.hpp"
#include "amp/core/parameters.hpp"

namespace amp::core {

struct MethodInfo {
  std::string name;
  std::string help;
  std::vector<ParamSpec> params;
};

// `Info` is MethodInfo or a struct extending it with what one family of methods declares more.
template <class Method, class Info = MethodInfo>
class MethodCatalog {
 public:
  using Factory = std::function<std::unique_ptr<Method>(const Params&)>;

  // `kind` names the methods in messages ("planner").
  explicit MethodCatalog(std::string kind = "method") : kind_(std::move(kind)) {}

  // Throws std::logic_error for a duplicate name (a programming error).
  void add(Info info, Factory factory) {
    std::string name = info.name;
    if (!entries_.emplace(name, Entry{std::move(info), std::move(factory)}).second) {
      throw std::logic_error(kind_ + " '" + name + "' registered twice");
    }
  }
  // Throws ParameterError for an unknown name (listing the valid ones) or a bad parameter.
  std::unique_ptr<Method> make(const std::string& name, const ParamMap& params) const {
    const Entry& e = entry(name);
    return e.factory(Params(name, e.info.params, params));
  }
  // Throws ParameterError for an unknown name.
  const Info& info(const std::string& name) const { return entry(name).info; }
  bool contains(const std::string& name) const { return entries_.count(name) != 0; }
  // Sorted names.
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& [n, e] : entries_) out.push_back(n);
    return out;
  }

 private:
  struct Entry {
    Info info;
    Factory factory;
  };
  const Entry& entry(const std::string& name) const {
    const auto it = entries_.find(name);
    if (it == entries_.end()) {
      std::string valid;
      for (const auto& [n, e] : entries_) valid += (valid.empty() ? "" : ", ") + n;
      throw ParameterError("unknown " + kind_ + " '" + name + "' (valid: " + valid + ")");
    }
    return it->second;
  }

  std::string kind_;
  std::map<std::string, Entry> entries_;
};

}  // namespace amp::core
