#pragma once
#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>
#include <yaml-cpp/yaml.h>

namespace amp::world {

// Reads typed fields from a YAML node with errors that name the file, the field path and the value:
// "maze.yaml: robot.shapes[0].circle.radius: expected a positive number, got '-1'".
class YamlFields {
 public:
  YamlFields(YAML::Node node, std::filesystem::path file, std::string path);

  const YAML::Node& node() const { return node_; }
  const std::filesystem::path& file() const { return file_; }
  const std::string& path() const { return path_; }

  bool has(std::string_view key) const;
  YamlFields child(std::string_view key) const;          // throws when missing
  YamlFields element(std::size_t i) const;               // of a sequence
  std::size_t size() const;                              // of a sequence; throws if not one
  bool is_sequence() const { return node_.IsSequence(); }
  bool is_map() const { return node_.IsMap(); }

  double number(std::string_view key) const;
  double number(std::string_view key, double fallback) const;
  double positive(std::string_view key) const;
  double positive(std::string_view key, double fallback) const;
  long long integer(std::string_view key, long long fallback) const;
  std::string string(std::string_view key) const;
  std::string string(std::string_view key, const std::string& fallback) const;
  bool boolean(std::string_view key, bool fallback) const;
  // A list of numbers; `expected_size` 0 means any length >= 1.
  std::vector<double> numbers(std::string_view key, std::size_t expected_size = 0) const;
  Eigen::Vector2d vec2(std::string_view key) const;
  Eigen::Vector3d vec3(std::string_view key) const;
  // This node itself as a list of numbers / of 2-D points.
  std::vector<double> as_numbers(std::size_t expected_size = 0) const;
  std::vector<Eigen::Vector2d> as_points2() const;
  // Resolves a path field relative to the directory of the file; throws if the file is missing.
  std::filesystem::path file_path(std::string_view key) const;

  // The keys of this mapping in file order; throws unless it is a mapping without duplicates.
  std::vector<std::string> keys() const;
  // Rejects keys not in `allowed` (catches typos in problem files).
  void allow_only(std::initializer_list<std::string_view> allowed) const;

  // Throws FileError "<file>: <path>[.<key>]: <what>".
  [[noreturn]] void fail(std::string_view key, const std::string& what) const;

 private:
  std::string field(std::string_view key) const;
  YAML::Node node_;
  std::filesystem::path file_;
  std::string path_;
};

// Loads a YAML file; throws FileError for a missing/unreadable file or malformed YAML (with line).
YAML::Node load_yaml_file(const std::filesystem::path& file);

}  // namespace amp::world
