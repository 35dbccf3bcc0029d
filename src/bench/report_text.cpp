#include "report_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "amp/bench/cost_metric.hpp"

#include "amp/viz/xml_escape.hpp"

namespace amp::bench::report_text {

namespace {

constexpr const char* kDash = "\u2013";
constexpr double kDefaultAlpha = 0.01;  // summarize()'s default, used if the JSON lacks it
constexpr double kSmallestP = 1e-4;     // below this a p-value prints as "p < 0.0001"

std::string printf_string(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string name_html(const std::string& name) { return "<strong>" + viz::xml_escape(name) + "</strong>"; }
std::string possessive_html(const std::string& name) { return name_html(name) + "\u2019s"; }
std::string quantity_html(const CostStyle& style) { return viz::xml_escape(style.quantity()); }

double alpha_of(const nlohmann::json& tests) {
  if (tests.contains("regwq")) {
    const double a = number_at(tests["regwq"], "alpha");
    if (std::isfinite(a)) return a;
  }
  return kDefaultAlpha;
}

bool computed(const nlohmann::json& t) {
  return t.value("status", std::string("ok")) == "ok" && std::isfinite(number_at(t, "p_value")) &&
         std::isfinite(number_at(t, "statistic"));
}

std::string not_computed(const nlohmann::json& t) {
  const std::string status = t.value("status", std::string("ok"));
  return "not computed (" + viz::xml_escape(status == "ok" ? "no finite statistic" : status) + ").";
}

// "<what> differ significantly (F(2, 717) = 5.04, p = 0.0071)." or "... do not differ ...".
std::string f_test_sentence(const std::string& title, const std::string& note, const nlohmann::json& t,
                            const std::string& what, double alpha) {
  std::string s = "<em>" + title + "</em>" + (note.empty() ? "" : " (" + note + ")") + ": ";
  if (!computed(t)) return s + not_computed(t);
  const double p = number_at(t, "p_value");
  s += what + (p < alpha ? " differ significantly" : " do not differ significantly");
  return s + " (F(" + degrees_of_freedom(number_at(t, "df1")) + ", " + degrees_of_freedom(number_at(t, "df2")) +
         ") = " + statistic(number_at(t, "statistic")) + ", " + viz::xml_escape(p_value(p)) + ").";
}

std::string kruskal_sentence(const nlohmann::json& t, double alpha, const CostStyle& style) {
  std::string s = "<em>Kruskal\u2013Wallis rank test</em>: ";
  if (!computed(t)) return s + not_computed(t);
  const double p = number_at(t, "p_value");
  s += style.higher() ? "the distributions of " + quantity_html(style) : std::string("the run-cost distributions");
  s += p < alpha ? " differ significantly in location" : " do not differ significantly in location";
  return s + " (H = " + statistic(number_at(t, "statistic")) + ", df = " + degrees_of_freedom(number_at(t, "df1")) +
         ", " + viz::xml_escape(p_value(p)) + ").";
}

// REGWQ's homogeneous subsets as "{a, b}", best mean first: summary.json lists them (and their
// members) by ascending mean, which is best first only when lower is better.
std::vector<std::string> regwq_subsets(const nlohmann::json& r, const CostStyle& style) {
  std::vector<std::string> subsets;
  for (const auto& sub : r.value("subsets", nlohmann::json::array())) {
    std::vector<std::string> names;
    for (const auto& n : sub) names.push_back(name_html(n.get<std::string>()));
    if (style.higher()) std::reverse(names.begin(), names.end());
    std::string list;
    for (std::size_t i = 0; i < names.size(); ++i) list += (i ? ", " : "") + names[i];
    subsets.push_back("{" + list + "}");
  }
  if (style.higher()) std::reverse(subsets.begin(), subsets.end());
  return subsets;
}

std::string regwq_sentence(const nlohmann::json& r, const CostStyle& style) {
  std::string s = "<em>REGWQ</em> at \u03b1 = " + real(number_at(r, "alpha")) + " (experimentwise): ";
  if (r.value("status", std::string("ok")) != "ok") {
    return s + "not computed (" + viz::xml_escape(r.value("status", std::string())) + ").";
  }
  const std::vector<std::string> subsets = regwq_subsets(r, style);
  // Who differs from whom; told planner by planner, the planner with most differences first, each
  // pair once (as the paper: "PRM-C's mean differs from PRM-G's and PRM-L's").
  std::map<std::string, std::set<std::string>> differs;
  std::vector<std::string> order;
  for (const auto& p : r.value("pairs", nlohmann::json::array())) {
    const std::string a = p.value("a", std::string()), b = p.value("b", std::string());
    for (const auto& n : {a, b}) {
      if (std::find(order.begin(), order.end(), n) == order.end()) order.push_back(n);
    }
    if (p.value("differs", false)) {
      differs[a].insert(b);
      differs[b].insert(a);
    }
  }
  if (differs.empty()) {
    return s + (style.higher() ? "no two means of " + quantity_html(style) : std::string("no two mean run costs")) +
           " differ significantly" + (subsets.size() == 1 ? " (one homogeneous subset " + subsets[0] + ")." : ".");
  }
  s += subsets.size() == 1 ? "homogeneous subset " : "homogeneous subsets ";
  if (style.higher() && subsets.size() > 1) s += "(highest means first) ";
  s += join_words(subsets) + ": ";
  std::vector<std::string> clauses;
  while (!differs.empty()) {
    std::string best = order.front();
    std::size_t most = 0;
    for (const auto& n : order) {
      const auto it = differs.find(n);
      if (it != differs.end() && it->second.size() > most) best = n, most = it->second.size();
    }
    std::vector<std::string> others;
    for (const auto& n : order) {  // in the experiment's order, not alphabetical
      if (differs[best].count(n) != 0) others.push_back(possessive_html(n));
    }
    for (const auto& n : differs[best]) {
      differs[n].erase(best);
      if (differs[n].empty()) differs.erase(n);
    }
    differs.erase(best);
    clauses.push_back(possessive_html(best) + " mean " + quantity_html(style) + " differs from " + join_words(others));
  }
  return s + join_words(clauses) + ".";
}

// A cost made of runs cut at a limit says more about the limit than about the method.
std::string censored(const nlohmann::json& p, const CostStyle& style) {
  const double n = number_at(p, "n"), solved = number_at(p, "solved");
  if (!(n > 0 && solved < n)) return std::string();
  return " \u2013 but " + count(n - solved) + " of its " + count(n) + " runs stopped at a limit, so this " +
         (style.higher() ? "mean" : "cost") + " is censored";
}

// "X has the lowest mean run cost (...)" (or the highest mean, when higher is better) and "Y has
// the lowest coefficient of variation (...)": a smaller spread is better whichever way the cost goes.
std::vector<std::string> best_sentences(const nlohmann::json& problem, const CostStyle& style) {
  std::vector<std::string> out;
  const auto& planners = problem.value("planners", nlohmann::json::array());
  const nlohmann::json* best_mean = nullptr;
  const nlohmann::json* low_cv = nullptr;
  for (const auto& p : planners) {
    const double mean = number_at(cost_json(p), "mean"), cv = number_at(cost_json(p), "cv_percent");
    const double best = best_mean ? number_at(cost_json(*best_mean), "mean") : 0.0;
    if (std::isfinite(mean) && (!best_mean || better(style.direction, mean, best))) best_mean = &p;
    if (std::isfinite(cv) && (!low_cv || cv < number_at(cost_json(*low_cv), "cv_percent"))) low_cv = &p;
  }
  if (planners.size() > 1 && best_mean != nullptr) {
    const std::string value = style.format(number_at(cost_json(*best_mean), "mean"));
    const std::string what = style.higher() ? " has the highest mean " + quantity_html(style) + " (" + value + ")"
                                            : " has the lowest mean run cost (" + value + " " +
                                                  viz::xml_escape(style.label) + ")";
    out.push_back(name_html(best_mean->value("name", std::string())) + what + censored(*best_mean, style) + ".");
  }
  if (low_cv != nullptr) {
    const std::string cv = percent(std::round(number_at(cost_json(*low_cv), "cv_percent")));
    out.push_back(name_html(low_cv->value("name", std::string())) +
                  (planners.size() > 1 ? " has the lowest coefficient of variation (" + cv + ")"
                                       : " has a coefficient of variation of " + cv) +
                  censored(*low_cv, style) + ".");
  }
  return out;
}

// "X 1 of 4 (1 timeout)"; a sequence of worlds says "sequences incomplete", since its status is the
// sequence's, not its worlds'.
std::string unsolved_item(const nlohmann::json& p) {
  const double n = number_at(p, "n"), solved = number_at(p, "solved");
  if (!(n > 0)) return name_html(p.value("name", std::string())) + " has no runs";
  std::vector<std::string> kinds;
  const nlohmann::json statuses = p.value("statuses", nlohmann::json::object());
  for (const auto& [status, k] : statuses.items()) {
    std::string words = status;
    std::replace(words.begin(), words.end(), '_', ' ');  // node_limit -> node limit
    if (status != "solved") kinds.push_back(count(k.get<double>()) + " " + viz::xml_escape(words));
  }
  const bool sequence = run_kind(p) == RunKind::kWorldSequence;
  return name_html(p.value("name", std::string())) + " " + count(n - solved) + " of " + count(n) +
         (sequence ? " sequences incomplete" : "") + " (" + join_words(kinds) + ")";
}

std::string unsolved_sentence(const nlohmann::json& problem) {
  std::vector<std::string> unsolved;
  for (const auto& p : problem.value("planners", nlohmann::json::array())) {
    const double n = number_at(p, "n"), solved = number_at(p, "solved");
    if (!(n > 0) || solved < n) unsolved.push_back(unsolved_item(p));
  }
  if (unsolved.empty()) return std::string();
  return "Not solved: " + join_words(unsolved) +
         ". Runs stopped at a limit count with the cost they had spent (censored at the limit).";
}

}  // namespace

std::string join_words(const std::vector<std::string>& items) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i > 0) out += i + 1 == items.size() ? " and " : ", ";
    out += items[i];
  }
  return out;
}

double number_at(const nlohmann::json& j, const char* key) {
  if (!j.is_object()) return std::numeric_limits<double>::quiet_NaN();
  const auto it = j.find(key);
  return it != j.end() && it->is_number() ? it->get<double>() : std::numeric_limits<double>::quiet_NaN();
}

std::string count(double v) {
  if (!std::isfinite(v)) return kDash;
  if (std::abs(v) < 100) return printf_string(v == std::round(v) ? "%.0f" : "%.3g", v);
  std::string digits = printf_string("%.0f", std::abs(v));
  std::string out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return v < 0 ? "-" + out : out;
}

std::string statistic(double v) {
  if (!std::isfinite(v)) return kDash;
  const double a = std::abs(v);
  return printf_string(a >= 100 ? "%.0f" : a >= 10 ? "%.1f" : "%.2f", v);
}

std::string degrees_of_freedom(double v) {
  if (!std::isfinite(v)) return kDash;
  return printf_string(std::abs(v - std::round(v)) < 1e-9 ? "%.0f" : "%.1f", v);
}

std::string p_value(double p) {
  if (!std::isfinite(p)) return std::string("p = ") + kDash;
  if (p < kSmallestP) return "p < 0.0001";
  return "p = " + printf_string("%.2g", p);
}

std::string percent(double v) {
  if (!std::isfinite(v)) return kDash;
  if (v == std::round(v)) return printf_string("%.0f", v) + "\u00a0%";
  return printf_string(std::abs(v) >= 10 ? "%.1f" : "%.2g", v) + "\u00a0%";
}

std::string seconds(double v) {
  if (!std::isfinite(v)) return kDash;
  if (std::abs(v) < 1.0) return printf_string("%.3g", v * 1e3) + "\u00a0ms";
  return printf_string("%.3g", v) + "\u00a0s";
}

std::string real(double v) {
  if (!std::isfinite(v)) return kDash;
  return printf_string("%.4g", v);
}

CostStyle cost_style(const std::string& metric, CostDirection direction) {
  CostStyle s;
  s.label = metric_label(metric);
  s.is_time = metric == "wall_time_s";
  s.direction = direction;
  return s;
}

RunKind run_kind(const nlohmann::json& planner) {
  if (planner.value("kind", std::string()) != "navigation") return RunKind::kPlanning;
  const bool worlds = planner.contains("metrics") && planner["metrics"].contains(kWorldsExtra);
  return worlds ? RunKind::kWorldSequence : RunKind::kNavigation;
}

const nlohmann::json& cost_json(const nlohmann::json& planner) {
  static const nlohmann::json kEmpty = nlohmann::json::object();
  if (planner.contains("cost")) return planner["cost"];
  return planner.contains("cd_calls") ? planner["cd_calls"] : kEmpty;
}

std::vector<std::string> findings(const nlohmann::json& problem, const CostStyle& style) {
  std::vector<std::string> out = best_sentences(problem, style);
  if (const std::string s = unsolved_sentence(problem); !s.empty()) out.push_back(s);
  if (!problem.contains("tests")) {
    out.push_back("One planner only: no tests between planners.");
    return out;
  }
  const auto& t = problem["tests"];
  if (t.contains("skipped")) {
    out.push_back("Tests between planners skipped: " + viz::xml_escape(t.value("skipped", std::string())) + ".");
    return out;
  }
  const double alpha = alpha_of(t);
  const auto test = [&](const char* key) { return t.value(key, nlohmann::json::object()); };
  const std::string q = quantity_html(style);
  out.push_back(f_test_sentence("Brown\u2013Forsythe test", "Levene\u2019s test about the medians",
                                test("levene_brown_forsythe"), "the variances of " + q, alpha));
  const std::string means = style.higher() ? "the means of " + q : std::string("the mean run costs");
  out.push_back(f_test_sentence("One-way ANOVA", "", test("anova"), means, alpha));
  out.push_back(f_test_sentence("Welch\u2019s ANOVA", "unequal variances", test("welch_anova"), means, alpha));
  out.push_back(kruskal_sentence(test("kruskal_wallis"), alpha, style));
  if (t.contains("regwq")) out.push_back(regwq_sentence(t["regwq"], style));
  out.push_back("Significance level \u03b1 = " + real(alpha) + " throughout.");
  return out;
}

}  // namespace amp::bench::report_text
