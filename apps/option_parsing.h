// Parsing of option values that CLI11 cannot check by itself; errors name the option.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace voltree::app {

// "512x384" -> {512, 384}; "512" -> {512, 512}.
std::pair<int, int> ParseSize(const std::string& option, const std::string& text);
// "7" -> 7 levels; "auto" -> 0, meaning: as many as the photos fill (reconstruct/auto_levels.h).
int ParseLevels(const std::string& option, const std::string& text);
// "0.1,-0.02" -> {0.1, -0.02}.
std::vector<double> ParseNumbers(const std::string& option, const std::string& text);

}  // namespace voltree::app
