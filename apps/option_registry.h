// Every flag of every command, registered once: its name, its help, and the library fields it
// sets. Commands add flags by name and bind them to their option structs, so a flag means the same
// thing wherever it appears, and its default is read off the struct that owns it (CLI11 captures
// the bound value), never written down twice. Library Check() messages name fields
// ("ReconstructOptions.levels"); FlagForField() turns them back into the flag a user typed.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/error.h"

namespace voltree::app {

struct OptionSpec {
  std::string flag;                 // as CLI11 takes it: "--levels", "-o,--output"
  std::vector<std::string> fields;  // the library fields it sets ("Struct.member"); empty: the command's own
  std::string help;
  // Flags every command reads its own way (what --force replaces, where -o writes): the command
  // words the help. All others carry the registry's help verbatim.
  bool worded_by_command = false;
};

// The registry, in the order --help lists a command's options.
const std::vector<OptionSpec>& RegisteredOptions();
// The spec of `flag` ("--levels" or "-o,--output"); throws std::logic_error when it is not
// registered, a programming error the registry test catches.
const OptionSpec& RegisteredOption(std::string_view flag);
// The long flag that sets `field`, e.g. "ReconstructOptions.levels" -> "--levels"; "" when none does.
std::string FlagForField(std::string_view field);
// A library OptionError as the command line says it: the flag instead of the field.
std::string DescribeOptionError(const OptionError& error);

// What to type instead of a flag that voltree no longer takes (a default that became the only
// behaviour, a flag turned around); empty when `argument` is not one.
std::string RetiredFlagAdvice(std::string_view argument);

// A registered option bound to `value`; its current value is shown as the default.
template <typename T>
CLI::Option* AddOption(CLI::App& command, std::string_view flag, T& value) {
  const OptionSpec& spec = RegisteredOption(flag);
  return command.add_option(spec.flag, value, spec.help)->capture_default_str();
}

// A registered option with the command's own help (worded_by_command flags only).
template <typename T>
CLI::Option* AddOption(CLI::App& command, std::string_view flag, T& value, const std::string& help) {
  const OptionSpec& spec = RegisteredOption(flag);
  if (!spec.worded_by_command) throw std::logic_error(spec.flag + " has the registry's help, not the command's");
  return command.add_option(spec.flag, value, help);
}

// A registered on/off flag. A "--no-..." flag turns `value` off.
CLI::Option* AddFlag(CLI::App& command, std::string_view flag, bool& value);
CLI::Option* AddFlag(CLI::App& command, std::string_view flag, bool& value, const std::string& help);

// A registered option whose text is parsed into `value` (levels "7|auto", sizes "512x384", choices).
// `show` names the current value for --help; `parse` throws Error naming the flag on bad text.
template <typename T>
CLI::Option* AddParsedOption(CLI::App& command, std::string_view flag, T& value,
                             std::function<void(const std::string&, T&)> parse, const std::string& shown_default) {
  const OptionSpec& spec = RegisteredOption(flag);
  return command
      .add_option_function<std::string>(
          spec.flag, [&value, parse](const std::string& text) { parse(text, value); }, spec.help)
      ->default_str(shown_default);
}

// A registered option choosing one of `names` (e.g. {"sart", kSart}, {"ceres", kCeres}).
template <typename T>
CLI::Option* AddChoice(CLI::App& command, std::string_view flag, T& value,
                       std::vector<std::pair<std::string, T>> names) {
  std::string shown, expected;
  for (const auto& [name, choice] : names) {
    if (choice == value) shown = name;
    expected += (expected.empty() ? "" : ", ") + name;
  }
  const std::string long_flag = RegisteredOption(flag).flag;
  return AddParsedOption<T>(
      command, flag, value,
      [names, expected, long_flag](const std::string& text, T& out) {
        for (const auto& [name, choice] : names)
          if (name == text) {
            out = choice;
            return;
          }
        Fail(long_flag, " '", text, "': expected one of ", expected);
      },
      shown);
}

}  // namespace voltree::app
