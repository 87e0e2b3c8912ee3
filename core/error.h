// Errors that reach the user. Every message says which file (and line or field) is wrong and what
// was expected, so the command line can print it as is.
#pragma once

#include <sstream>
#include <stdexcept>
#include <string>

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

// "FILE:LINE: message", the form compilers use, so editors can jump to it.
template <typename... Args>
[[noreturn]] void FailAt(const std::string& file, int line, const Args&... args) {
  throw Error(Str(file, ":", line, ": ", args...));
}

}  // namespace voltree
