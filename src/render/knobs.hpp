#pragma once
/// @file knobs.hpp
/// @brief A technique's accuracy knobs as name=value pairs: declared with defaults and help, validated,
/// and recorded verbatim in stats and bench tables.
#include <map>
#include <utility>
#include <string>
#include <vector>

namespace lucent::render {

struct KnobSpec {
  std::string name, defaultValue, help;
};

class Knobs {
 public:
  Knobs(const std::vector<KnobSpec>& specs, const std::map<std::string, std::string>& given,
        const std::string& method);
  double number(const std::string& name) const;
  const std::string& text(const std::string& name) const;
  /// The knob as a number in [lo, hi] (an integer if `integer`); throws InputError naming the range.
  double numberIn(const std::string& name, double lo, double hi, bool integer = false) const;
  int integer(const std::string& name, int lo, int hi) const { return int(numberIn(name, lo, hi, true)); }
  /// The value paired with the knob's text; throws InputError listing the names.
  template <class T>
  T choice(const std::string& name, const std::vector<std::pair<std::string, T>>& options) const {
    std::string names;
    for (const auto& [option, value] : options) {
      if (option == text(name)) return value;
      names += (names.empty() ? "" : " or ") + option;
    }
    throwNotOneOf(name, names);
  }
  const std::map<std::string, std::string>& values() const { return mValues; }
  /// "a=1;b=2", stable order, for tables; with onlyChanged, just the knobs that differ from their defaults.
  std::string summary(bool onlyChanged = false) const;

 private:
  [[noreturn]] void throwNotOneOf(const std::string& name, const std::string& names) const;
  std::map<std::string, std::string> mValues, mDefaults;
  std::string mMethod;
};

/// "spacing=0.1,fraction=0.5" -> map; throws InputError on a malformed pair.
std::map<std::string, std::string> parseKnobList(const std::string& text);

}  // namespace lucent::render
