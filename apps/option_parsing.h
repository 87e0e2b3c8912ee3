// Parsing of option values that CLI11 cannot check by itself; errors name the option and quote
// the text given.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace voltree::app {

// "512x384" -> {512, 384}; "512" -> {512, 512}.
std::pair<int, int> ParseSize(const std::string& option, const std::string& text);
// "7" -> 7 levels (1..99); "auto" is handled by the caller.
int ParseLevels(const std::string& option, const std::string& text);
// "0.1,-0.02" -> {0.1, -0.02}.
std::vector<double> ParseNumbers(const std::string& option, const std::string& text);
// "42" -> 42: digits only, no sign.
uint64_t ParseCount(const std::string& option, const std::string& text);
// "1048576", "1MiB", "900KiB", "2GiB" -> bytes (binary units; "0": none).
uint64_t ParseBytes(const std::string& option, const std::string& text);
// "R,G,B" with components 0..255 -> opaque straight RGBA in [0, 1].
std::array<float, 4> ParseBackground(const std::string& option, const std::string& text);

}  // namespace voltree::app
