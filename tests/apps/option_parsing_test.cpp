#include "apps/option_parsing.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace voltree::app {
namespace {

TEST(OptionParsing, SizesAreWidthByHeightOrOneNumberForASquare) {
  EXPECT_EQ(ParseSize("--size", "640x480"), std::make_pair(640, 480));
  EXPECT_EQ(ParseSize("--size", "512"), std::make_pair(512, 512));
  EXPECT_THROW(ParseSize("--size", "0x4"), Error);
  EXPECT_THROW(ParseSize("--size", "64x48x2"), Error);
  try {
    ParseSize("--size", "wide");
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("--size 'wide'"), std::string::npos) << error.what();
  }
}

TEST(OptionParsing, BackgroundsAreOpaqueRgb) {
  const auto background = ParseBackground("--background", "255,0,51");
  EXPECT_FLOAT_EQ(background[0], 1.0f);
  EXPECT_FLOAT_EQ(background[2], 0.2f);
  EXPECT_FLOAT_EQ(background[3], 1.0f);
  EXPECT_THROW(ParseBackground("--background", "300,0,0"), Error);
  EXPECT_THROW(ParseBackground("--background", "1,2"), Error);
}

TEST(OptionParsing, LevelsCountsAndNumbers) {
  EXPECT_EQ(ParseLevels("--levels", "7"), 7);
  EXPECT_THROW(ParseLevels("--levels", "0"), Error);
  EXPECT_THROW(ParseLevels("--levels", "many"), Error);
  EXPECT_EQ(ParseCount("--seed", "42"), 42u);
  EXPECT_EQ(ParseBytes("--max-bytes", "1048576"), 1048576u);
  EXPECT_EQ(ParseBytes("--max-bytes", "1MiB"), 1048576u);
  EXPECT_EQ(ParseBytes("--max-bytes", "900KiB"), 921600u);
  EXPECT_EQ(ParseBytes("--max-bytes", "2GiB"), uint64_t(2) << 30);
  EXPECT_EQ(ParseBytes("--max-bytes", "0"), 0u);
  for (const char* bad : {"1MB", "-1", "1.5MiB", "", "MiB"}) EXPECT_THROW(ParseBytes("--max-bytes", bad), Error) << bad;
  EXPECT_THROW(ParseCount("--seed", "-1"), Error);
  EXPECT_EQ(ParseNumbers("--distortion", "0.1,-0.02"), (std::vector<double>{0.1, -0.02}));
  EXPECT_THROW(ParseNumbers("--distortion", "0.1,x"), Error);
}

}  // namespace
}  // namespace voltree::app
