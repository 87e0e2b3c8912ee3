#include "apps/option_parsing.h"

#include <regex>
#include <sstream>

#include "core/error.h"

namespace voltree::app {

std::pair<int, int> ParseSize(const std::string& option, const std::string& text) {
  static const std::regex kSize(R"((\d{1,5})(?:[xX](\d{1,5}))?)");
  std::smatch match;
  if (!std::regex_match(text, match, kSize))
    Fail(option, " '", text, "': expected WIDTHxHEIGHT (e.g. 512x512) or one number for a square");
  const int width = std::stoi(match[1].str());
  const int height = match[2].matched ? std::stoi(match[2].str()) : width;
  if (width < 1 || height < 1) Fail(option, " '", text, "': width and height must be at least 1 pixel");
  return {width, height};
}

int ParseLevels(const std::string& option, const std::string& text) {
  static const std::regex kCount(R"(\d{1,2})");
  if (!std::regex_match(text, kCount) || std::stoi(text) < 1)
    Fail(option, " '", text, "': expected a number of levels (e.g. 7) or auto");
  return std::stoi(text);
}

std::vector<double> ParseNumbers(const std::string& option, const std::string& text) {
  std::vector<double> numbers;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    size_t used = 0;
    double value = 0;
    try {
      value = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != item.size()) Fail(option, " '", text, "': '", item, "' is not a number");
    numbers.push_back(value);
  }
  return numbers;
}

uint64_t ParseCount(const std::string& option, const std::string& text) {
  static const std::regex kDigits(R"(\d{1,19})");
  if (!std::regex_match(text, kDigits)) Fail(option, " '", text, "': expected a whole number such as 42");
  return std::stoull(text);
}

uint64_t ParseBytes(const std::string& option, const std::string& text) {
  static const std::regex kBytes(R"((\d{1,12})\s*(KiB|MiB|GiB)?)");
  std::smatch match;
  if (!std::regex_match(text, match, kBytes))
    Fail(option, " '", text, "': expected bytes such as 1048576, 900KiB or 1MiB (0: no limit)");
  const std::string unit = match[2].str();
  const int shift = unit == "KiB" ? 10 : unit == "MiB" ? 20 : unit == "GiB" ? 30 : 0;
  return std::stoull(match[1].str()) << shift;
}

std::array<float, 4> ParseBackground(const std::string& option, const std::string& text) {
  static const std::regex kRgb(R"((\d{1,3}),(\d{1,3}),(\d{1,3}))");
  std::smatch match;
  if (!std::regex_match(text, match, kRgb) || std::stoi(match[1]) > 255 || std::stoi(match[2]) > 255 ||
      std::stoi(match[3]) > 255)
    Fail(option, " '", text, "': expected R,G,B with components 0..255 such as 135,180,230");
  return {std::stoi(match[1]) / 255.0f, std::stoi(match[2]) / 255.0f, std::stoi(match[3]) / 255.0f, 1.0f};
}

}  // namespace voltree::app
