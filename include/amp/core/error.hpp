#pragma once
#include <stdexcept>
#include <string>

namespace amp {

// Every error caused by user input, configuration or I/O. The message is one line and names the
// file, field and value at fault; `amp` prints it as `amp: error: <message>`.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
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
