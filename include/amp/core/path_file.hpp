#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "amp/core/space.hpp"

namespace amp::core {

enum class PathFormat {
  kText,  // OMPL.app `.path`: one state per line, coordinates separated by spaces
          // (SE2: x y theta; SE3: x y z qx qy qz qw; linkages: joint values)
  kYaml,  // `space: <kind>` and `states: [[...], ...]`
};

// Throws ParameterError for a name other than "path"/"text" or "yaml".
PathFormat path_format_from_string(const std::string& name);

std::string format_path(const Space& space, const std::vector<State>& path, PathFormat format);
// Reads either format (YAML when the file starts with a mapping); every state must have the space's
// dimension and lie in its bounds. Throws FileError naming the file and line.
std::vector<State> read_path_file(const std::filesystem::path& file, const Space& space);

}  // namespace amp::core
