// Errors that reach the user. Every message says which file (and line or field) is wrong and what
// was expected, so the command line can print it as is.
#pragma once

#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace voltree {

// A problem with the user's input or environment; the app prints what() and exits non-zero.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Concatenates anything streamable; GCC 12 has no std::format.
template <typename... Args>
std::string Str(const Args&... args) {
  std::ostringstream out;
  (out << ... << args);
  return out.str();
}

template <typename... Args>
[[noreturn]] void Fail(const Args&... args) {
  throw Error(Str(args...));
}

// A field of an options struct holds a value its Check() refuses. The message names the field as
// "Struct.member" (e.g. "ReconstructOptions.levels must be at least 1, got 0"); the command line
// replaces the field with the flag that set it.
class OptionError : public Error {
 public:
  OptionError(std::string field, std::string problem)
      : Error(field + " " + problem), field_(std::move(field)), problem_(std::move(problem)) {}
  const std::string& field() const { return field_; }
  const std::string& problem() const { return problem_; }  // the message after the field's name

 private:
  std::string field_, problem_;
};

template <typename... Args>
[[noreturn]] void FailOption(std::string field, const Args&... args) {
  throw OptionError(std::move(field), Str(args...));
}

// "FILE:LINE: message", the form compilers use, so editors can jump to it.
template <typename... Args>
[[noreturn]] void FailAt(const std::string& file, int line, const Args&... args) {
  throw Error(Str(file, ":", line, ": ", args...));
}

}  // namespace voltree
