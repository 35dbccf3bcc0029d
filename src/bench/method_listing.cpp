#include "amp/bench/method_listing.hpp"

#include <string>

#include "amp/core/method_catalog.hpp"
#include "amp/nav/navigator_catalog.hpp"
#include "amp/roadmap/catalog/planner_registry.hpp"
#include "amp/world/problem.hpp"

namespace amp::bench {

namespace {

// What a family of methods declares beyond its parameters: nothing for navigation methods ...
void list_limits(std::ostream&, const core::MethodInfo&) {}

// ... and for a planner the node limit a run gets when no one gives one.
void list_limits(std::ostream& out, const roadmap::PlannerInfo& info) {
  const std::size_t n = info.default_node_limit;
  out << "      default node limit: " << (n == world::kNoNodeLimit ? std::string("none") : std::to_string(n)) << '\n';
}

template <class Method, class Info>
void list_catalog(std::ostream& out, const char* heading, const core::MethodCatalog<Method, Info>& catalog) {
  out << heading << ":\n";
  if (catalog.names().empty()) out << "  (none registered)\n";
  for (const std::string& name : catalog.names()) {
    const auto& info = catalog.info(name);
    out << "  " << name << "  " << info.help << '\n';
    list_limits(out, info);
    for (const auto& p : info.params) {
      out << "      " << p.name << " (" << core::to_string(p.type) << ", default " << p.default_value.to_string();
      if (p.type == core::ParamType::kInteger || p.type == core::ParamType::kReal) {
        out << ", range [" << p.min << ", " << p.max << "]";
      }
      if (!p.choices.empty()) {
        out << ", one of";
        for (const auto& c : p.choices) out << ' ' << c;
      }
      out << ")  " << p.help << '\n';
    }
  }
}

}  // namespace

void list_methods(std::ostream& out) {
  list_catalog(out, "Planners", roadmap::builtin_planners());
  out << '\n';
  list_catalog(out, "Navigation methods", nav::builtin_navigators());
}

}  // namespace amp::bench
