// `prm-c`, `prm-g`, `prm-l`: PRM with a competence-controlled A* grid local planner (Isto 2003),
// one planner per form of the competence threshold O_th.
#include <memory>
#include <string>
#include <vector>

#include "amp/roadmap/catalog/planner_registry.hpp"
#include "amp/roadmap/competence/competence_prm.hpp"

namespace amp::roadmap {

void register_competence_prms(PlannerRegistry& registry) {
  struct Form {
    CompetenceKind kind;
    const char* name;
    const char* what;
  };
  const Form forms[] = {
      {CompetenceKind::kStatic, "prm-c", "static competence O_th = o"},
      {CompetenceKind::kGlobal, "prm-g", "global competence O_th = (S / s) * 32"},
      {CompetenceKind::kLocal, "prm-l", "local competence O_th = 1 + n / r_s(v)"},
  };
  for (const Form& f : forms) {
    std::vector<core::ParamSpec> specs = {competence_spec(f.kind)};
    for (const core::ParamSpec& s : CompetencePrmSettings::schema().specs()) specs.push_back(s);
    const std::string what = std::string("PRM with a bidirectional A* grid local planner (Isto 2003), ") + f.what;
    registry.add(PlannerInfo{{f.name, what, specs}}, [f](const core::Params& p) -> std::unique_ptr<Planner> {
      CompetencePrmSettings s = CompetencePrmSettings::schema().read(p);
      s.kind = f.kind;
      s.value = p.real(competence_parameter(f.kind));
      return std::make_unique<CompetencePrm>(s);
    });
  }
}

}  // namespace amp::roadmap
