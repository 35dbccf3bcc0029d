#include "amp/study/output_dir.hpp"

#include "amp/core/error.hpp"

namespace amp::study {

void check_writable(const std::filesystem::path& file, bool force, const std::string& option) {
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec)) {
    throw Error(option + ": '" + file.string() + "' is a directory, expected a file name");
  }
  if (std::filesystem::exists(file, ec) && !force) {
    throw Error(option + ": '" + file.string() + "' already exists (use --force to overwrite it)");
  }
  const auto parent = file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
  if (!std::filesystem::is_directory(parent, ec)) {
    throw Error(option + ": directory '" + parent.string() + "' does not exist");
  }
}

void check_output_dir(const std::filesystem::path& dir, const std::vector<std::string>& files, bool force,
                      const std::string& option) {
  std::error_code ec;
  if (std::filesystem::exists(dir, ec)) {
    if (!std::filesystem::is_directory(dir, ec)) {
      throw Error(option + ": '" + dir.string() + "' is a file, expected a directory");
    }
    for (const std::string& f : files) check_writable(dir / f, force, option);
    return;
  }
  const auto parent = dir.has_parent_path() ? dir.parent_path() : std::filesystem::path(".");
  if (!std::filesystem::is_directory(parent, ec)) {
    throw Error(option + ": directory '" + parent.string() + "' does not exist");
  }
}

void create_output_dir(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw FileError(dir.string() + ": cannot create the directory: " + ec.message());
}

}  // namespace amp::study
