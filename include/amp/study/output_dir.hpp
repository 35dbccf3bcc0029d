#pragma once
#include <filesystem>
#include <string>
#include <vector>

// Where a study's files go: the checks every command makes before any work (nothing the user wrote
// is overwritten without --force), and the folder made when the files are written.
namespace amp::study {

// Refuses to overwrite an existing file unless `force`; also refuses a directory or a path whose
// parent directory does not exist. `option` names the command-line option in the one-line error.
void check_writable(const std::filesystem::path& file, bool force, const std::string& option);

// Refuses a `dir` that is a file, one of `files` in it that exists (unless `force`), or a missing
// parent directory of a `dir` that does not exist yet.
void check_output_dir(const std::filesystem::path& dir, const std::vector<std::string>& files, bool force,
                      const std::string& option);

// Creates `dir` (and its parents); FileError with one line when it cannot.
void create_output_dir(const std::filesystem::path& dir);

}  // namespace amp::study
