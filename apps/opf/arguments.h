#pragma once
// A small command-line parser for the subcommands: `--name value` options and `--flag` switches,
// each declared with its help text, so --help is generated from the same declarations.

#include <optional>
#include <string>
#include <vector>

namespace opf::cli {

struct OptionSpec {
  std::string name;        ///< without the leading dashes
  std::string value_name;  ///< empty for a switch
  std::string help;
};

/// Thrown for a bad command line; main prints it with the subcommand's usage.
struct UsageError {
  std::string message;
};

class Arguments {
 public:
  /// Parses `args` (after the subcommand name). Throws UsageError on an unknown option, a missing
  /// value or a repeated option. "--help" and "-h" set help().
  Arguments(const std::vector<std::string>& args, const std::vector<OptionSpec>& specs);

  bool help() const { return help_; }
  bool has(const std::string& name) const;
  std::optional<std::string> get(const std::string& name) const;
  std::string require(const std::string& name) const;
  /// The value as a number; throws UsageError naming the option when it is not one.
  std::optional<unsigned long long> get_count(const std::string& name) const;
  /// The value as a finite decimal number; throws UsageError naming the option when it is not one.
  std::optional<double> get_number(const std::string& name) const;

 private:
  std::vector<std::pair<std::string, std::string>> values_;
  bool help_ = false;
};

/// Splits a command line into options (with their values) and positional arguments: every option
/// takes the next argument as its value except --help / -h and the switches of `specs`.
struct SplitCommandLine {
  std::vector<std::string> options;
  std::vector<std::string> positional;
};
SplitCommandLine split_positional(const std::vector<std::string>& raw,
                                  const std::vector<OptionSpec>& specs);

/// "a,b,,c" -> {"a", "b", "c"}: the comma-separated lists of options like --estimators.
std::vector<std::string> split_list(const std::string& text);

/// "Usage: opf <command> ...\n" followed by one line per option.
std::string usage(const std::string& command, const std::string& summary,
                  const std::vector<OptionSpec>& specs);

}  // namespace opf::cli
