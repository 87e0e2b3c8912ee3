// Runs the built `voltree` binary (VOLTREE_BINARY, set by tests/CMakeLists.txt) with shell
// arguments, for the end-to-end tests of the pipeline commands.
#pragma once

#include <cstdlib>
#include <string>

namespace voltree::test {

// The command's exit status as std::system returns it (0 on success).
inline int Voltree(const std::string& arguments) {
  return std::system((std::string(VOLTREE_BINARY) + " " + arguments).c_str());
}

}  // namespace voltree::test
