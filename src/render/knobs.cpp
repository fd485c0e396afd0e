#include "knobs.hpp"

#include <cmath>
#include <sstream>

#include "../cli/args.hpp"
#include "../util/error.hpp"

namespace lucent::render {

Knobs::Knobs(const std::vector<KnobSpec>& specs, const std::map<std::string, std::string>& given,
             const std::string& method)
    : mMethod(method) {
  for (const auto& s : specs) mValues[s.name] = mDefaults[s.name] = s.defaultValue;
  for (const auto& [k, v] : given) {
    if (!mValues.count(k)) {
      std::string names;
      for (const auto& s : specs) names += (names.empty() ? "" : ", ") + s.name;
      throw InputError("method '" + method + "' has no knob '" + k + "'; its knobs are: " + names);
    }
    mValues[k] = v;
  }
}

double Knobs::number(const std::string& name) const {
  return cli::parseNumber(text(name), "method '" + mMethod + "' knob " + name);
}

double Knobs::numberIn(const std::string& name, double lo, double hi, bool integer) const {
  const double v = number(name);
  if (!(v >= lo && v <= hi) || (integer && v != std::floor(v))) {
    std::ostringstream range;
    range << "[" << lo << ", " << hi << "]";
    throw InputError("method '" + mMethod + "' knob " + name + " must be " + (integer ? "an integer " : "") + "in " +
                     range.str() + ", not " + text(name));
  }
  return v;
}

void Knobs::throwNotOneOf(const std::string& name, const std::string& names) const {
  throw InputError("method '" + mMethod + "' knob " + name + " must be " + names + ", not '" + text(name) + "'");
}

const std::string& Knobs::text(const std::string& name) const { return mValues.at(name); }

std::string Knobs::summary(bool onlyChanged) const {
  std::string s;
  for (const auto& [k, v] : mValues)
    if (!onlyChanged || v != mDefaults.at(k)) s += (s.empty() ? "" : ";") + k + "=" + v;
  return s.empty() ? "defaults" : s;
}

std::map<std::string, std::string> parseKnobList(const std::string& text) {
  std::map<std::string, std::string> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    const auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError("knob '" + item + "' must be written name=value, e.g. spacing=0.1");
    out[item.substr(0, eq)] = item.substr(eq + 1);
  }
  return out;
}

}  // namespace lucent::render
