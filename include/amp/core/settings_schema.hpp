#pragma once
// Each parameter of a method written once: its name, range, choices and help sit in a schema beside
// the method's Settings struct, its default in the struct's own initialiser. The catalog reads the
// schema (`amp bench --list`, the checks on user input), and Settings::validate() runs the very same
// checks on a struct built in code, so the two cannot drift.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "amp/core/parameters.hpp"

namespace amp::core {

// One parameter of a Settings struct S: how to read it from S and how to set it from checked Params.
template <class S>
struct SettingsField {
  ParamSpec spec;  // default_value is filled in from S{} by SettingsSchema
  std::function<ParamValue(const S&)> get;
  std::function<void(S&, const Params&)> set;
};

template <class S>
class SettingsSchema {
 public:
  SettingsSchema(std::string owner, std::vector<SettingsField<S>> fields) : owner_(std::move(owner)) {
    const S defaults{};
    for (SettingsField<S>& f : fields) {
      f.spec.default_value = f.get(defaults);
      specs_.push_back(f.spec);
    }
    fields_ = std::move(fields);
  }

  const std::string& owner() const { return owner_; }
  const std::vector<ParamSpec>& specs() const { return specs_; }
  const std::vector<SettingsField<S>>& fields() const { return fields_; }

  // The parameters' values in `s`, by name.
  ParamMap values(const S& s) const {
    ParamMap out;
    for (const SettingsField<S>& f : fields_) out.emplace(f.spec.name, f.get(s));
    return out;
  }
  // S{} with every field read from `p` (checked against specs()).
  S read(const Params& p) const {
    S s{};
    for (const SettingsField<S>& f : fields_) f.set(s, p);
    return s;
  }
  // Throws ParameterError, worded as for user input, when a field of `s` is out of its range or
  // not one of its choices.
  void validate(const S& s) const { Params(owner_, specs_, values(s)); }

 private:
  std::string owner_;
  std::vector<SettingsField<S>> fields_;
  std::vector<ParamSpec> specs_;
};

// Field builders. `ref` is a member pointer (&S::k) or a callable returning a reference into S
// ([](S& s) -> int& { return s.inner.k; }).
template <class S, class Ref>
SettingsField<S> integer_field(std::string name, Ref ref, double min, double max, std::string help) {
  return {{name, ParamType::kInteger, 0.0, min, max, {}, std::move(help)},
          [ref](const S& s) { S c = s; return ParamValue(static_cast<double>(std::invoke(ref, c))); },
          [ref, n = name](S& s, const Params& p) {
            auto& v = std::invoke(ref, s);
            v = static_cast<std::remove_reference_t<decltype(v)>>(p.integer(n));
          }};
}

template <class S, class Ref>
SettingsField<S> real_field(std::string name, Ref ref, double min, double max, std::string help) {
  return {{name, ParamType::kReal, 0.0, min, max, {}, std::move(help)},
          [ref](const S& s) { S c = s; return ParamValue(std::invoke(ref, c)); },
          [ref, n = name](S& s, const Params& p) { std::invoke(ref, s) = p.real(n); }};
}

template <class S, class Ref>
SettingsField<S> bool_field(std::string name, Ref ref, std::string help) {
  return {{name, ParamType::kBool, 0.0, 0, 1, {}, std::move(help)},
          [ref](const S& s) { S c = s; return ParamValue(std::invoke(ref, c) ? 1.0 : 0.0); },
          [ref, n = name](S& s, const Params& p) { std::invoke(ref, s) = p.boolean(n); }};
}

// A choice stored as a string.
template <class S, class Ref>
SettingsField<S> choice_field(std::string name, Ref ref, std::vector<std::string> choices, std::string help) {
  return {{name, ParamType::kChoice, 0.0, 0, 0, std::move(choices), std::move(help)},
          [ref](const S& s) { S c = s; return ParamValue(std::string(std::invoke(ref, c))); },
          [ref, n = name](S& s, const Params& p) { std::invoke(ref, s) = p.choice(n); }};
}

// A choice stored as an enum: `names` pairs each word with its value, in the order listed.
template <class S, class Ref, class E>
SettingsField<S> enum_field(std::string name, Ref ref, std::vector<std::pair<std::string, E>> names, std::string help) {
  std::vector<std::string> words;
  for (const auto& [w, e] : names) words.push_back(w);
  return {{name, ParamType::kChoice, 0.0, 0, 0, std::move(words), std::move(help)},
          [ref, names](const S& s) {
            S c = s;
            const E v = std::invoke(ref, c);
            for (const auto& [w, e] : names) {
              if (e == v) return ParamValue(w);
            }
            return ParamValue(std::string("?"));  // not a listed value: validate() reports it
          },
          [ref, names, n = name](S& s, const Params& p) {
            for (const auto& [w, e] : names) {
              if (w == p.choice(n)) std::invoke(ref, s) = e;
            }
          }};
}

// The fields of a nested Settings struct Sub, reached from S through `part`.
template <class S, class Sub, class Part>
std::vector<SettingsField<S>> nested_fields(const SettingsSchema<Sub>& sub, Part part) {
  std::vector<SettingsField<S>> out;
  for (const SettingsField<Sub>& f : sub.fields()) {
    out.push_back({f.spec, [part, get = f.get](const S& s) { S c = s; return get(std::invoke(part, c)); },
                   [part, set = f.set](S& s, const Params& p) { set(std::invoke(part, s), p); }});
  }
  return out;
}

}  // namespace amp::core
