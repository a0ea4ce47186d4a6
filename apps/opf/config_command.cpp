#include "config_command.h"

#include "arguments.h"
#include "command_help.h"
#include "estimator_arguments.h"
#include "opf/io/estimator_settings_yaml.h"

#include <iostream>

namespace opf::cli {
namespace {

std::vector<OptionSpec> specs() {
  std::vector<OptionSpec> s = {
      {"dump", "", "print the effective settings as YAML (required)"},
  };
  for (auto& spec : estimator_option_specs())
    if (spec.name != "seed" && spec.name != "threads") s.push_back(std::move(spec));
  return s;
}

constexpr const char* kSummary =
    "Prints every estimator setting with the value a run with the same options would use: the\n"
    "defaults, then --preset, then --config, then --camera and --particles. The output is a\n"
    "settings file (--config takes it back) and what result files record under provenance.";

}  // namespace

CommandHelp config_help() {
  return {"config", kSummary, specs()};
}

int config_command(const std::vector<std::string>& raw) {
  const auto option_specs = specs();
  const Arguments args(raw, option_specs);
  if (args.help()) {
    std::cout << usage(config_help());
    return 0;
  }
  if (!args.has("dump")) throw UsageError{"nothing to do: pass --dump"};
  std::cout << dump_estimator_settings(settings_from(args));
  return 0;
}

}  // namespace opf::cli
