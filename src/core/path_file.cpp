#include "amp/core/path_file.hpp"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "amp/core/error.hpp"

namespace amp::core {

namespace {
// Enough digits that a path read back is the path written (round-trip of doubles).
constexpr int kDigits = 17;

std::vector<double> parse_numbers(const std::string& text, bool& ok) {
  std::vector<double> v;
  std::istringstream in(text);
  std::string tok;
  ok = true;
  while (in >> tok) {
    char* end = nullptr;
    const double x = std::strtod(tok.c_str(), &end);
    if (end == tok.c_str() || *end != '\0' || !std::isfinite(x)) {
      ok = false;
      return v;
    }
    v.push_back(x);
  }
  return v;
}
}  // namespace

PathFormat path_format_from_string(const std::string& name) {
  if (name == "path" || name == "text") return PathFormat::kText;
  if (name == "yaml") return PathFormat::kYaml;
  throw ParameterError("unknown path format '" + name + "' (expected path or yaml)");
}

std::string format_path(const Space& space, const std::vector<State>& path, PathFormat format) {
  std::ostringstream out;
  out << std::setprecision(kDigits);
  if (format == PathFormat::kYaml) {
    out << "space: " << space.kind() << "\nstates:\n";
    for (const State& s : path) {
      out << "  - [";
      for (int i = 0; i < s.size(); ++i) out << (i ? ", " : "") << s[i];
      out << "]\n";
    }
    return out.str();
  }
  for (const State& s : path) {
    for (int i = 0; i < s.size(); ++i) out << (i ? " " : "") << s[i];
    out << '\n';
  }
  return out.str();
}

std::vector<State> read_path_file(const std::filesystem::path& file, const Space& space) {
  std::ifstream in(file);
  if (!in) throw FileError(file.string() + ": cannot open path file");
  std::vector<State> path;
  std::string line;
  int line_no = 0;
  bool yaml = false;
  while (std::getline(in, line)) {
    ++line_no;
    std::string text = line.substr(0, line.find('#'));
    if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
    if (text.rfind("space:", 0) == 0 || text.rfind("states:", 0) == 0) {
      yaml = true;
      continue;
    }
    if (yaml) {
      // "  - [a, b, c]" lines of the YAML form written by format_path.
      const auto l = text.find('['), r = text.rfind(']');
      if (l == std::string::npos || r == std::string::npos || r < l) {
        throw FileError(file.string() + ":" + std::to_string(line_no) + ": expected '- [numbers]'");
      }
      text = text.substr(l + 1, r - l - 1);
      for (char& c : text) c = c == ',' ? ' ' : c;
    }
    bool ok = false;
    const std::vector<double> v = parse_numbers(text, ok);
    if (!ok) throw FileError(file.string() + ":" + std::to_string(line_no) + ": not a list of numbers");
    if (static_cast<int>(v.size()) != space.dimension()) {
      throw FileError(file.string() + ":" + std::to_string(line_no) + ": expected " +
                      std::to_string(space.dimension()) + " numbers per state, got " + std::to_string(v.size()));
    }
    State s(space.dimension());
    for (int i = 0; i < space.dimension(); ++i) s[i] = v[i];
    if (space.kind() == "se3" && s.tail<4>().norm() > 0) s.tail<4>().normalize();
    if (!space.in_bounds(s)) {
      throw FileError(file.string() + ":" + std::to_string(line_no) + ": state is outside the space's bounds");
    }
    path.push_back(s);
  }
  if (path.empty()) throw FileError(file.string() + ": the path file holds no states");
  return path;
}

}  // namespace amp::core
