#include "args.hpp"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>

#include <lucent/technique/validity.hpp>

#include "../util/error.hpp"

namespace lucent::cli {

Args::Args(std::string command, std::string usage, std::vector<OptionSpec> specs)
    : mCommand(std::move(command)), mUsage(std::move(usage)), mSpecs(std::move(specs)) {}

const OptionSpec* Args::find(const std::string& name) const {
  for (const auto& s : mSpecs)
    if (s.name == name) return &s;
  return nullptr;
}

void Args::fail(const std::string& message) const {
  throw InputError("lucent " + mCommand + ": " + message + " (see 'lucent " + mCommand +
                   " --help')");
}

bool Args::parseOptionsOnly(int argc, char** argv) {
  parse(argc, argv, 2);
  if (helpRequested()) {
    std::cout << helpText();
    return false;
  }
  if (!positional().empty()) fail("unexpected argument '" + positional().front() + "'");
  return true;
}

void Args::parse(int argc, char** argv, int first) {
  for (int i = first; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      mHelp = true;
      continue;
    }
    if (arg.rfind("--", 0) != 0 || arg.size() == 2) {
      mPositional.push_back(arg);
      continue;
    }
    std::string name = arg.substr(2), value;
    bool inlineValue = false;
    if (const auto eq = name.find('='); eq != std::string::npos) {
      value = name.substr(eq + 1);
      name = name.substr(0, eq);
      inlineValue = true;
    }
    const OptionSpec* spec = find(name);
    if (!spec) fail("unknown option '--" + name + "'");
    if (spec->value.empty()) {
      if (inlineValue) fail("option '--" + name + "' takes no value");
      value = "1";
    } else if (!inlineValue) {
      if (i + 1 >= argc) fail("option '--" + name + "' needs a value " + spec->value);
      value = argv[++i];
    }
    auto& slot = mValues[name];
    if (!slot.empty() && !spec->repeatable) fail("option '--" + name + "' is given twice");
    slot.push_back(value);
  }
}

std::string Args::helpText() const {
  std::ostringstream out;
  out << "usage: " << mUsage << "\n\noptions:\n";
  for (const auto& s : mSpecs) {
    std::string left = "  --" + s.name + (s.value.empty() ? "" : " " + s.value);
    out << left << std::string(left.size() < 30 ? 30 - left.size() : 1, ' ') << s.help
        << (s.repeatable ? " (repeatable)" : "") << "\n";
  }
  out << "  --help" << std::string(24, ' ') << "this text\n";
  return out.str();
}

std::string Args::get(const std::string& name, const std::string& fallback) const {
  const auto it = mValues.find(name);
  return it == mValues.end() ? fallback : it->second.back();
}

std::vector<std::string> Args::all(const std::string& name) const {
  const auto it = mValues.find(name);
  return it == mValues.end() ? std::vector<std::string>{} : it->second;
}

double parseNumber(const std::string& text, const std::string& what) {
  const char* begin = text.c_str();
  char* end = nullptr;
  const double v = std::strtod(begin, &end);
  if (text.empty() || end == begin || *end != '\0' || !std::isfinite(v))
    throw InputError(what + ": '" + text + "' is not a number; write e.g. 1.5 or 2e-3");
  return v;
}

std::vector<double> parseList(const std::string& text, const std::string& what) {
  std::vector<double> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) out.push_back(parseNumber(item, what));
  if (out.empty())
    throw InputError(what + ": empty list; write comma-separated numbers, e.g. 0,0.1,1");
  return out;
}

glm::dvec3 parseTriple(const std::string& text, const std::string& what) {
  const std::vector<double> v = parseList(text, what);
  if (v.size() == 1) return glm::dvec3(v[0]);
  if (v.size() != 3)
    throw InputError(what + ": '" + text + "' needs 3 comma-separated numbers R,G,B (or X,Y,Z)");
  return {v[0], v[1], v[2]};
}

double Args::number(const std::string& name, double fallback, double lo, double hi) const {
  if (!has(name)) return fallback;
  const double v = parseNumber(get(name), "lucent " + mCommand + ": --" + name);
  if (v < lo || v > hi)
    fail("--" + name + " " + get(name) + " is out of range; use a value in [" +
         technique::valueText(lo) + ", " + technique::valueText(hi) + "]");
  return v;
}

int Args::integer(const std::string& name, int fallback, int lo, int hi) const {
  const double v = number(name, fallback, lo, hi);
  if (v != std::floor(v)) fail("--" + name + " needs a whole number, not " + get(name));
  return int(v);
}

glm::dvec3 Args::triple(const std::string& name, glm::dvec3 fallback) const {
  return has(name) ? parseTriple(get(name), "lucent " + mCommand + ": --" + name) : fallback;
}

std::vector<double> Args::list(const std::string& name) const {
  return parseList(get(name), "lucent " + mCommand + ": --" + name);
}

}  // namespace lucent::cli
