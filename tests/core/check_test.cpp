#include "core/check.h"

#include <gtest/gtest.h>

namespace voltree {
namespace {

int Checked(int members, int capacity) {
  VT_CHECK(members <= capacity, members, " members in ", capacity, " slots");
  return capacity - members;
}

TEST(Check, AFailedInvariantIsAnInternalErrorNamingWhereAndWhat) {
  EXPECT_EQ(Checked(2, 3), 1);
  try {
    Checked(4, 3);
    FAIL() << "no error";
  } catch (const InvariantError& error) {
    const std::string what = error.what();
    EXPECT_NE(what.find("check_test.cpp:"), std::string::npos) << what;
    EXPECT_NE(what.find("'members <= capacity' failed: 4 members in 3 slots"), std::string::npos) << what;
  }
  // Not an Error: the command line reports it as a bug of voltree, not as the user's mistake.
  EXPECT_THROW(Checked(5, 3), std::logic_error);
  EXPECT_FALSE((std::is_base_of_v<Error, InvariantError>));
}

TEST(Check, WithoutAMessage) {
  const auto check = [](bool ok) { VT_CHECK(ok); };
  EXPECT_NO_THROW(check(true));
  EXPECT_THROW(check(false), InvariantError);
}

}  // namespace
}  // namespace voltree
