// Numbers for people: a fixed number of decimals ("28.03"), for progress lines and tables.
#pragma once

#include <cstdio>
#include <string>

namespace voltree {

inline std::string FixedDecimals(double value, int digits) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", digits, value);
  return text;
}

}  // namespace voltree
