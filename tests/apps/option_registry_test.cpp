#include "apps/option_registry.h"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <sstream>

#include "apps/stage_options.h"
#include "apps/voltree_app.h"
#include "reconstruct/reconstruct.h"

namespace voltree::app {
namespace {

// Every option of every command, as (command name, option), help and positional arguments aside.
std::vector<std::pair<std::string, const CLI::Option*>> CommandOptions(CLI::App& app) {
  std::vector<std::pair<std::string, const CLI::Option*>> options;
  for (CLI::App* command : app.get_subcommands([](CLI::App*) { return true; }))
    for (const CLI::Option* option : command->get_options())
      if (option->nonpositional() && option != command->get_help_ptr())
        options.emplace_back(command->get_name(), option);
  return options;
}

TEST(OptionRegistry, EveryFlagOfEveryCommandIsRegisteredWithOneMeaning) {
  const auto app = MakeVoltreeApp();
  std::map<std::string, std::set<std::string>> meanings;  // flag -> descriptions
  const auto options = CommandOptions(*app);
  ASSERT_GT(options.size(), 100u);
  for (const auto& [command, option] : options) {
    const std::string flag = option->get_name();
    const OptionSpec* spec = nullptr;
    EXPECT_NO_THROW(spec = &RegisteredOption(flag)) << command << " " << flag;
    if (!spec || spec->worded_by_command) continue;
    EXPECT_EQ(option->get_description(), spec->help) << command << " " << flag;
    meanings[flag].insert(option->get_description());
  }
  for (const auto& [flag, descriptions] : meanings) EXPECT_EQ(descriptions.size(), 1u) << flag;
}

TEST(OptionRegistry, EveryRegisteredFlagIsUsedAndEveryFieldHasOneFlag) {
  const auto app = MakeVoltreeApp();
  std::set<std::string> used;
  for (const auto& [command, option] : CommandOptions(*app)) used.insert(option->get_name());
  std::set<std::string> fields;
  for (const OptionSpec& spec : RegisteredOptions()) {
    EXPECT_TRUE(used.count(RegisteredOption(spec.flag).flag.substr(spec.flag.rfind(',') + 1)))
        << spec.flag << " is registered but no command has it";
    for (const std::string& field : spec.fields) EXPECT_TRUE(fields.insert(field).second) << field;
  }
}

// The line of `help` that lists `flag` in its option column ("-o,--output TEXT=."), not in
// another option's description; "" when none does.
std::string HelpLine(const std::string& help, const std::string& flag) {
  std::istringstream lines(help);
  for (std::string line; std::getline(lines, line);) {
    const size_t start = line.find_first_not_of(' ');
    if (start == std::string::npos || line[start] != '-') continue;
    std::istringstream names(line.substr(start, line.find("  ", start) - start));
    for (std::string name; std::getline(names, name, ',');)
      if (name.substr(0, name.find_first_of(" =")) == flag) return line;
  }
  return "";
}

TEST(OptionRegistry, HelpListsEachOptionWithTheDefaultOfItsStruct) {
  const auto app = MakeVoltreeApp();
  for (CLI::App* command : app->get_subcommands([](CLI::App*) { return true; })) {
    const std::string help = command->help();
    for (const CLI::Option* option : command->get_options()) {
      if (!option->nonpositional() || option == command->get_help_ptr()) continue;
      const std::string line = HelpLine(help, option->get_name());
      EXPECT_NE(line, "") << command->get_name() << " --help does not list " << option->get_name();
      // The default, on the option's own line, as CLI11 shows it: "--levels INT=7".
      if (!option->get_default_str().empty()) {
        EXPECT_NE(line.find("=" + option->get_default_str()), std::string::npos)
            << command->get_name() << " " << option->get_name() << ": no default in '" << line << "'";
      }
    }
  }
  // The defaults are the option structs' own, in every command that shows them.
  const ReconstructOptions defaults;
  for (const char* name : {"reconstruct", "run", "demo"}) {
    CLI::App* command = app->get_subcommand(name);
    EXPECT_EQ(command->get_option("--levels")->get_default_str(), std::to_string(defaults.levels)) << name;
    EXPECT_EQ(command->get_option("--iterations")->get_default_str(), std::to_string(defaults.opacity.sart.iterations))
        << name;
    EXPECT_EQ(command->get_option("--solver")->get_default_str(), "sart") << name;
  }
}

TEST(OptionRegistry, LibraryFieldsAreReportedAsFlags) {
  ReconstructOptions options;
  options.fit.iterations = -1;
  try {
    options.Check();
    FAIL() << "no error";
  } catch (const OptionError& error) {
    EXPECT_EQ(error.field(), "BillboardFitOptions.iterations");
    EXPECT_EQ(DescribeOptionError(error), "--fit-iterations must be >= 0, got -1");
  }
  EXPECT_EQ(FlagForField("ReconstructOptions.levels"), "--levels");
  EXPECT_EQ(FlagForField("OpacityOptions.nothing"), "");
}

void Parse(CLI::App& command, std::vector<std::string> args) {
  args.insert(args.begin(), "voltree");
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  command.parse(int(argv.size()), argv.data());
}

TEST(OptionRegistry, FlagsSetTheNestedStageOptions) {
  CLI::App command;
  ReconstructOptions options;
  AddReconstructOptions(command, options);
  Parse(command, {"--levels", "auto", "--solver", "ceres", "--prune", "0.5", "--no-fit", "--iterations", "12"});
  EXPECT_TRUE(options.auto_levels);
  EXPECT_EQ(options.opacity.solver, SolverKind::kCeres);
  EXPECT_EQ(options.billboards.prune, 0.5);
  EXPECT_FALSE(options.fit.enabled);
  EXPECT_EQ(options.opacity.sart.iterations, 12);
  EXPECT_EQ(options.levels, ReconstructOptions().levels);  // auto: chosen once the photos are read

  CLI::App other;
  ReconstructOptions bad;
  AddReconstructOptions(other, bad);
  try {
    Parse(other, {"--solver", "gauss"});
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_EQ(std::string(error.what()), "--solver 'gauss': expected one of sart, ceres");
  }
}

TEST(OptionRegistry, OneSeedForTheTreeAndItsSurroundings) {
  CLI::App command;
  TreeSource tree;
  StudioOptions studio;
  AddTreeSourceOptions(command, tree, studio);
  AddStudioOptions(command, studio);
  Parse(command, {"--seed", "7", "--size", "300x200", "--mesh-up", "z"});
  EXPECT_EQ(tree.seed, 7u);
  EXPECT_EQ(studio.seed, 7u);
  EXPECT_EQ(studio.width, 300);
  EXPECT_EQ(studio.height, 200);
  EXPECT_EQ(tree.up, UpAxis::kZ);
}

}  // namespace
}  // namespace voltree::app
