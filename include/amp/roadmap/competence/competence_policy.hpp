#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "amp/core/parameters.hpp"
#include "amp/roadmap/local_planners/local_planner.hpp"

namespace amp::roadmap {

enum class CompetenceKind { kStatic, kGlobal, kLocal };  // PRM-C, PRM-G, PRM-L

// Each form's own parameter (o, s or n): name, default, range and help, written once; the catalog
// lists it and the policies check their value against it.
const core::ParamSpec& competence_spec(CompetenceKind kind);
// "o", "s" or "n".
const char* competence_parameter(CompetenceKind kind);

// Sets the A* local planner's competence threshold O_th for each edge PRM asks for (Isto et al.;
// docs/run-cost-variance.md). Implementations: StaticCompetence (PRM-C), GlobalCompetence (PRM-G), LocalCompetence
// (PRM-L). One per run: policies learn from the outcomes they are told.
class CompetencePolicy {
 public:
  virtual ~CompetencePolicy() = default;
  virtual double threshold(const EdgeRequest& edge) = 0;
  virtual void record(const EdgeRequest& /*edge*/, bool /*success*/) {}
};

// PRM-C: a fixed O_th = o.
class StaticCompetence final : public CompetencePolicy {
 public:
  explicit StaticCompetence(double o);  // throws ParameterError outside competence_spec(kStatic)
  double threshold(const EdgeRequest&) override { return o_; }

 private:
  double o_;
};

// PRM-G: O_th = (S / s) * 32, S the roadmap's size when the edge is asked for. Below S = s / 32 the
// threshold is under 1, which no search can meet (O >= 1), so the roadmap first grows by sampling.
class GlobalCompetence final : public CompetencePolicy {
 public:
  explicit GlobalCompetence(double s);  // throws ParameterError outside competence_spec(kGlobal)
  double threshold(const EdgeRequest& edge) override;

 private:
  double s_;
  std::size_t last_size_ = 0;  // for requests without a roadmap size
};

// PRM-L: per vertex v, r_s(v) = (N_s(v) + 1) / (N(v) + 1) over the local-planner calls with v as
// either end, O_th(v) = 1 + n / r_s(v); the larger of the two ends' thresholds is used.
class LocalCompetence final : public CompetencePolicy {
 public:
  explicit LocalCompetence(double n);  // throws ParameterError outside competence_spec(kLocal)
  double threshold(const EdgeRequest& edge) override;
  void record(const EdgeRequest& edge, bool success) override;
  // r_s(v); 1 for a vertex never tried.
  double success_ratio(std::size_t v) const;

 private:
  double vertex_threshold(std::size_t v) const { return 1.0 + n_ / success_ratio(v); }
  void count(std::size_t v, bool success);

  double n_;
  std::vector<std::uint32_t> calls_, successes_;
};

}  // namespace amp::roadmap
