// Option structs validate themselves: Check() throws an Error that names the field at fault.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "core/error.h"

namespace voltree::testing {

// `options.Check()` throws an Error whose message names `field`.
template <typename Options>
void ExpectCheckNames(const Options& options, const std::string& field) {
  try {
    options.Check();
    ADD_FAILURE() << "expected an Error naming " << field;
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find(field), std::string::npos) << error.what();
  }
}

}  // namespace voltree::testing
