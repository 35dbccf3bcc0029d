#include "amp/world/yaml_fields.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <system_error>

#include "amp/core/error.hpp"

namespace amp::world {

namespace {

std::string scalar_text(const YAML::Node& n) {
  if (n.IsScalar()) return n.Scalar();
  if (n.IsSequence()) return "a list";
  if (n.IsMap()) return "a mapping";
  return "nothing";
}

}  // namespace

YAML::Node load_yaml_file(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) {
    throw FileError(file.string() + ": cannot open file");
  }
  std::stringstream text;
  text << in.rdbuf();
  try {
    return YAML::Load(text.str());
  } catch (const YAML::Exception& e) {
    throw FileError(file.string() + ": malformed YAML at line " + std::to_string(e.mark.line + 1) + ", column " +
                    std::to_string(e.mark.column + 1) + ": " + e.msg);
  }
}

YamlFields::YamlFields(YAML::Node node, std::filesystem::path file, std::string path)
    : node_(std::move(node)), file_(std::move(file)), path_(std::move(path)) {}

std::string YamlFields::field(std::string_view key) const {
  if (key.empty()) return path_.empty() ? std::string("(top level)") : path_;
  if (path_.empty()) return std::string(key);
  return path_ + "." + std::string(key);
}

void YamlFields::fail(std::string_view key, const std::string& what) const {
  throw FileError(file_.string() + ": " + field(key) + ": " + what);
}

bool YamlFields::has(std::string_view key) const {
  return node_.IsMap() && node_[std::string(key)].IsDefined() && !node_[std::string(key)].IsNull();
}

YamlFields YamlFields::child(std::string_view key) const {
  if (!node_.IsMap()) fail("", "expected a mapping, got " + scalar_text(node_));
  if (!has(key)) fail(key, "missing required field");
  return YamlFields(node_[std::string(key)], file_, field(key));
}

YamlFields YamlFields::element(std::size_t i) const {
  if (!node_.IsSequence() || i >= node_.size()) fail("", "missing list element " + std::to_string(i));
  return YamlFields(node_[i], file_, path_ + "[" + std::to_string(i) + "]");
}

std::size_t YamlFields::size() const {
  if (!node_.IsSequence()) fail("", "expected a list, got " + scalar_text(node_));
  return node_.size();
}

double YamlFields::number(std::string_view key) const {
  const YamlFields c = child(key);
  if (!c.node_.IsScalar()) fail(key, "expected a number, got " + scalar_text(c.node_));
  double v = 0.0;
  if (!YAML::convert<double>::decode(c.node_, v) || !std::isfinite(v)) {
    fail(key, "expected a number, got '" + c.node_.Scalar() + "'");
  }
  return v;
}

double YamlFields::number(std::string_view key, double fallback) const {
  return has(key) ? number(key) : fallback;
}

double YamlFields::positive(std::string_view key) const {
  const double v = number(key);
  if (!(v > 0.0)) fail(key, "expected a positive number, got '" + node_[std::string(key)].Scalar() + "'");
  return v;
}

double YamlFields::positive(std::string_view key, double fallback) const {
  return has(key) ? positive(key) : fallback;
}

long long YamlFields::integer(std::string_view key, long long fallback) const {
  if (!has(key)) return fallback;
  const YamlFields c = child(key);
  long long v = 0;
  if (!c.node_.IsScalar() || !YAML::convert<long long>::decode(c.node_, v)) {
    fail(key, "expected an integer, got '" + scalar_text(c.node_) + "'");
  }
  return v;
}

std::string YamlFields::string(std::string_view key) const {
  const YamlFields c = child(key);
  if (!c.node_.IsScalar()) fail(key, "expected a string, got " + scalar_text(c.node_));
  return c.node_.Scalar();
}

std::string YamlFields::string(std::string_view key, const std::string& fallback) const {
  return has(key) ? string(key) : fallback;
}

bool YamlFields::boolean(std::string_view key, bool fallback) const {
  if (!has(key)) return fallback;
  const YamlFields c = child(key);
  bool v = false;
  if (!c.node_.IsScalar() || !YAML::convert<bool>::decode(c.node_, v)) {
    fail(key, "expected true or false, got '" + scalar_text(c.node_) + "'");
  }
  return v;
}

std::vector<double> YamlFields::as_numbers(std::size_t expected_size) const {
  if (!node_.IsSequence()) fail("", "expected a list of numbers, got " + scalar_text(node_));
  if (expected_size != 0 && node_.size() != expected_size) {
    fail("", "expected " + std::to_string(expected_size) + " numbers, got " + std::to_string(node_.size()));
  }
  if (node_.size() == 0) fail("", "expected a non-empty list of numbers");
  std::vector<double> out;
  out.reserve(node_.size());
  for (std::size_t i = 0; i < node_.size(); ++i) {
    double v = 0.0;
    if (!node_[i].IsScalar() || !YAML::convert<double>::decode(node_[i], v) || !std::isfinite(v)) {
      fail("", "element " + std::to_string(i) + " is not a number ('" + scalar_text(node_[i]) + "')");
    }
    out.push_back(v);
  }
  return out;
}

std::vector<double> YamlFields::numbers(std::string_view key, std::size_t expected_size) const {
  return child(key).as_numbers(expected_size);
}

Eigen::Vector2d YamlFields::vec2(std::string_view key) const {
  const auto v = numbers(key, 2);
  return {v[0], v[1]};
}

Eigen::Vector3d YamlFields::vec3(std::string_view key) const {
  const auto v = numbers(key, 3);
  return {v[0], v[1], v[2]};
}

std::vector<Eigen::Vector2d> YamlFields::as_points2() const {
  const std::size_t n = size();
  std::vector<Eigen::Vector2d> pts;
  pts.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto v = element(i).as_numbers(2);
    pts.emplace_back(v[0], v[1]);
  }
  return pts;
}

std::filesystem::path YamlFields::file_path(std::string_view key) const {
  const std::filesystem::path rel = string(key);
  const std::filesystem::path full = rel.is_absolute() ? rel : file_.parent_path() / rel;
  std::error_code ec;  // a name the OS refuses (too long, ...) is "no such file", not an exception
  if (!std::filesystem::is_regular_file(full, ec)) fail(key, "no such file '" + full.string() + "'");
  return full;
}

std::vector<std::string> YamlFields::keys() const {
  if (!node_.IsMap()) fail("", "expected a mapping, got " + scalar_text(node_));
  std::vector<std::string> out;
  for (const auto& kv : node_) {
    std::string key = kv.first.Scalar();
    if (std::find(out.begin(), out.end(), key) != out.end()) {
      fail(key, "duplicate field (again at line " + std::to_string(kv.first.Mark().line + 1) + ")");
    }
    out.push_back(std::move(key));
  }
  return out;
}

void YamlFields::allow_only(std::initializer_list<std::string_view> allowed) const {
  if (!node_.IsMap()) fail("", "expected a mapping, got " + scalar_text(node_));
  std::set<std::string> seen;
  for (const auto& kv : node_) {
    const std::string key = kv.first.Scalar();
    // yaml-cpp keeps both copies of a repeated key and lookups see only the first: say so instead.
    if (!seen.insert(key).second) {
      fail(key, "duplicate field (again at line " + std::to_string(kv.first.Mark().line + 1) + ")");
    }
    bool ok = false;
    for (std::string_view a : allowed) ok = ok || a == key;
    if (!ok) {
      std::string names;
      for (std::string_view a : allowed) names += (names.empty() ? "" : ", ") + std::string(a);
      fail(key, "unknown field (expected one of: " + names + ")");
    }
  }
}

}  // namespace amp::world
