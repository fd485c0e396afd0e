#pragma once
/// @file args.hpp
/// @brief Command-line options of one subcommand: declared with their help, parsed strictly, with
/// one-line errors that name the option, the problem and the fix.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace lucent::cli {

struct OptionSpec {
  std::string name;   ///< without the leading "--"
  std::string value;  ///< placeholder shown in help ("FILE", "X"); empty for a flag
  std::string help;
  bool repeatable = false;
};

class Args {
 public:
  Args(std::string command, std::string usage, std::vector<OptionSpec> specs);

  /// Parses argv[first..]; throws InputError on unknown options, missing values, repeats.
  void parse(int argc, char** argv, int first);
  bool helpRequested() const { return mHelp; }
  /// For a subcommand that takes options only: parses argv[2..], prints the help when asked
  /// (returns false: the command is done), fails on a positional argument; true: run.
  bool parseOptionsOnly(int argc, char** argv);
  std::string helpText() const;

  bool has(const std::string& name) const { return mValues.count(name) > 0; }
  std::string get(const std::string& name, const std::string& fallback = "") const;
  std::vector<std::string> all(const std::string& name) const;
  const std::vector<std::string>& positional() const { return mPositional; }
  /// Every option given, by name (without "--"), with its values.
  const std::map<std::string, std::vector<std::string>>& given() const { return mValues; }

  double number(const std::string& name, double fallback, double lo, double hi) const;
  int integer(const std::string& name, int fallback, int lo, int hi) const;
  glm::dvec3 triple(const std::string& name, glm::dvec3 fallback) const;
  std::vector<double> list(const std::string& name) const;

  /// An InputError message prefixed with "lucent <command>: " and ending with the help pointer.
  [[noreturn]] void fail(const std::string& message) const;
  const std::string& command() const { return mCommand; }

 private:
  const OptionSpec* find(const std::string& name) const;
  std::string mCommand, mUsage;
  std::vector<OptionSpec> mSpecs;
  std::map<std::string, std::vector<std::string>> mValues;
  std::vector<std::string> mPositional;
  bool mHelp = false;
};

/// Strict number parsing: the whole string must be a finite number. Throws InputError naming
/// `what`.
double parseNumber(const std::string& text, const std::string& what);
glm::dvec3 parseTriple(const std::string& text, const std::string& what);
std::vector<double> parseList(const std::string& text, const std::string& what);

}  // namespace lucent::cli
