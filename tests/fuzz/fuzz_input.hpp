#pragma once
// Shared by the libFuzzer targets (tests/fuzz/*_fuzz.cpp). AMP's readers take file names, so each
// input is written to a file in a scratch directory that also links the bundled files the formats
// refer to (problems/maps, problems/ompl, problems/puzzle, tests/data/meshes, the problems
// themselves), so that a corpus file from problems/ loads there as it does in the source tree.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include "amp/core/error.hpp"

namespace amp::fuzz {

// The scratch directory of this process (created on first use; removed at exit).
const std::filesystem::path& workdir();

// Writes the input to workdir()/name (replacing the last input) and returns its path.
std::filesystem::path write_input(const std::uint8_t* data, std::size_t size, const std::string& name);

// Aborts when an error message spans lines or echoes raw bytes (control bytes, or bytes that are not UTF-8).
void check_one_line(const char* message);

// Runs `parse`; an amp::Error is the expected reply to a bad input. Any other exception escapes,
// and libFuzzer reports it as a crash: a reader must turn every fault into a one-line amp::Error.
template <class F>
void expect_amp_errors_only(F&& parse) {
  try {
    parse();
  } catch (const amp::Error& e) {
    check_one_line(e.what());
  }
}

}  // namespace amp::fuzz
