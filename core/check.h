// Internal invariants: a failed VT_CHECK is a bug in voltree, not in the user's input. Errors a
// user can cause (bad files, bad options) go through Fail() in core/error.h instead.
#pragma once

#include <stdexcept>

#include "core/error.h"

namespace voltree {

// What a failed VT_CHECK throws; the command line reports it as an internal error.
class InvariantError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

}  // namespace voltree

// Checked in every build type: the invariants guarded are cheap next to the work around them.
#define VT_CHECK(condition, ...)                                                                           \
  do {                                                                                                     \
    if (!(condition))                                                                                      \
      throw ::voltree::InvariantError(::voltree::Str(__FILE__, ":", __LINE__, ": invariant '", #condition, \
                                                     "' failed" __VA_OPT__(, ": ", ) __VA_ARGS__));        \
  } while (false)
