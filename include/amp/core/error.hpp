#pragma once
#include <stdexcept>
#include <string>
#include <string_view>

namespace amp {

// `text` fit for a one-line message: control bytes and bytes that are not UTF-8 become \xNN, so
// that an error quoting a value read from a file never echoes the file's raw bytes into a terminal.
std::string printable(std::string_view text);

// Every error caused by user input, configuration or I/O. The message is one line and names the
// file, field and value at fault; `amp` prints it as `amp: error: <message>`. The constructor
// escapes it with printable(), whatever the thrower quoted.
class Error : public std::runtime_error {
 public:
  explicit Error(std::string_view message) : std::runtime_error(printable(message)) {}
};

// A file that cannot be read or parsed (problem files, meshes, maps).
class FileError : public Error {
 public:
  using Error::Error;
};

// A parameter outside its range, of the wrong type or unknown.
class ParameterError : public Error {
 public:
  using Error::Error;
};

}  // namespace amp
