#pragma once
/// @file knob.hpp
/// @brief A technique's knobs, typed: kind, default, range or choices, unit, help, and the phase a
/// change invalidates. The one place a knob's name, default and range are written; every front end
/// (CLI, bench, VTK filter, generated ParaView XML, GPU pass) reads them from here.
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace lucent::technique {

/// A request a technique cannot serve (unknown knob, value out of range, missing capability): the
/// message names the problem and the fix. Front ends report it as bad input (the CLI: one line,
/// exit code 2).
class RequestError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// The upper end of a range that has none.
inline constexpr double kUnbounded = std::numeric_limits<double>::infinity();

enum class KnobKind { Integer, Real, Choice, Text, OutputFile };

/// What a change of the knob invalidates: the prepared structures (atlas, samples, graph), or only
/// a frame.
enum class Phase { Prepare, Frame };

inline const char* kindName(KnobKind k) {
  switch (k) {
    case KnobKind::Integer:
      return "integer";
    case KnobKind::Real:
      return "real";
    case KnobKind::Choice:
      return "choice";
    case KnobKind::Text:
      return "text";
    case KnobKind::OutputFile:
      return "output-file";
  }
  return "?";
}
inline const char* phaseName(Phase p) { return p == Phase::Prepare ? "prepare" : "frame"; }

struct KnobSpec {
  std::string name;
  KnobKind kind = KnobKind::Real;
  std::string defaultValue;
  double min = -std::numeric_limits<double>::infinity();  ///< Integer, Real
  double max = std::numeric_limits<double>::infinity();
  bool minExclusive = false;         ///< Real: value > min rather than >= min
  std::vector<std::string> choices;  ///< Choice
  std::string extension;             ///< OutputFile: required file ending (".vtu")
  std::string unit;                  ///< "mm", "mm^-1", "degrees", "" (count)
  std::string help;
  Phase invalidates = Phase::Frame;

  static KnobSpec integer(std::string name, long long def, long long lo, long long hi,
                          std::string help, Phase phase = Phase::Frame, std::string unit = "") {
    KnobSpec k = make(std::move(name), KnobKind::Integer, std::to_string(def));
    k.min = double(lo), k.max = double(hi), k.help = std::move(help), k.invalidates = phase,
    k.unit = std::move(unit);
    return k;
  }
  static KnobSpec real(std::string name, std::string def, double lo, double hi, std::string unit,
                       std::string help, Phase phase = Phase::Frame, bool loExclusive = false) {
    KnobSpec k = make(std::move(name), KnobKind::Real, std::move(def));
    k.min = lo, k.max = hi, k.minExclusive = loExclusive, k.unit = std::move(unit),
    k.help = std::move(help);
    k.invalidates = phase;
    return k;
  }
  /// The default is `def`, or the first option when `def` is empty.
  static KnobSpec choice(std::string name, std::vector<std::string> options, std::string help,
                         Phase phase = Phase::Frame, std::string def = "") {
    KnobSpec k =
        make(std::move(name), KnobKind::Choice, def.empty() ? options.front() : std::move(def));
    k.choices = std::move(options), k.help = std::move(help), k.invalidates = phase;
    return k;
  }
  static KnobSpec text(std::string name, std::string def, std::string help,
                       Phase phase = Phase::Prepare) {
    KnobSpec k = make(std::move(name), KnobKind::Text, std::move(def));
    k.help = std::move(help), k.invalidates = phase;
    return k;
  }
  /// An optional file the technique writes (empty = none); front ends check its folder before any
  /// work.
  static KnobSpec outputFile(std::string name, std::string extension, std::string help) {
    KnobSpec k = make(std::move(name), KnobKind::OutputFile, "");
    k.extension = std::move(extension), k.help = std::move(help);
    return k;
  }

  static KnobSpec make(std::string name, KnobKind kind, std::string def) {
    KnobSpec k;
    k.name = std::move(name), k.kind = kind, k.defaultValue = std::move(def);
    return k;
  }

  /// The range as people read it: "[1, 4096]", "> 0", ">= 0", or "mip or row".
  std::string rangeText() const {
    if (kind == KnobKind::Choice) {
      std::string s;
      for (const auto& c : choices) s += (s.empty() ? "" : " or ") + c;
      return s;
    }
    std::ostringstream o;
    if (std::isinf(max))
      o << std::setprecision(12) << (minExclusive ? "> " : ">= ") << min;
    else
      o << std::setprecision(12) << (minExclusive ? "(" : "[") << min << ", " << max << "]";
    return o.str();
  }
};

/// "chart-angle" -> "ChartAngle": the mechanical CamelCase of a knob or technique name that VTK and
/// ParaView properties use (each '-'-separated word capitalised, the rest kept as written).
inline std::string camelCase(const std::string& name) {
  std::string out;
  bool upper = true;
  for (const char ch : name) {
    if (ch == '-' || ch == '_' || ch == '.') {
      upper = true;
      continue;
    }
    out += upper ? char(std::toupper(static_cast<unsigned char>(ch))) : ch;
    upper = false;
  }
  return out;
}

namespace detail {
inline bool parseReal(const std::string& text, double& value) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text.front()))) return false;
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);  // subnormal values parse too (std::stod would throw)
  return *end == '\0' && std::isfinite(value);
}
}  // namespace detail

/// The value of every knob of one technique: the defaults, overridden by what was given, each
/// checked against its spec when constructed (so a bad value fails before any work).
class KnobValues {
 public:
  KnobValues() = default;
  KnobValues(const std::vector<KnobSpec>& specs,
             const std::vector<std::pair<std::string, std::string>>& given,
             const std::string& technique)
      : mSpecs(specs), mTechnique(technique) {
    for (const auto& s : specs) mValues.push_back(s.defaultValue);
    for (const auto& [name, value] : given) mValues[indexOf(name)] = value;
    for (std::size_t i = 0; i < specs.size(); ++i) validate(specs[i], mValues[i]);
  }

  const std::string& text(const std::string& name) const { return mValues[indexOf(name)]; }
  double real(const std::string& name) const {
    double v = 0;
    detail::parseReal(text(name), v);
    return v;
  }
  long long integer(const std::string& name) const { return static_cast<long long>(real(name)); }
  /// The value paired with the knob's choice; the options must be exactly the spec's choices (in
  /// any order).
  template <class T>
  T pick(const std::string& name, const std::vector<std::pair<std::string, T>>& options) const {
    const KnobSpec& spec = mSpecs[indexOf(name)];
    if (options.size() != spec.choices.size())
      throw std::logic_error("knob " + name + ": the options do not match the spec's choices");
    for (const auto& [option, value] : options)
      if (option == text(name)) return value;
    throw std::logic_error("knob " + name + ": choice '" + text(name) + "' has no value");
  }

  const std::vector<KnobSpec>& specs() const { return mSpecs; }
  const std::string& technique() const { return mTechnique; }
  /// (name, value) in the spec's order.
  std::vector<std::pair<std::string, std::string>> values() const {
    std::vector<std::pair<std::string, std::string>> out;
    for (std::size_t i = 0; i < mSpecs.size(); ++i) out.emplace_back(mSpecs[i].name, mValues[i]);
    return out;
  }
  /// "a=1;b=2" in the spec's order, for tables; with onlyChanged, just the knobs that differ from
  /// their defaults.
  std::string summary(bool onlyChanged = false) const {
    std::string s;
    for (std::size_t i = 0; i < mSpecs.size(); ++i)
      if (!onlyChanged || mValues[i] != mSpecs[i].defaultValue)
        s += (s.empty() ? "" : ";") + mSpecs[i].name + "=" + mValues[i];
    return s.empty() ? "defaults" : s;
  }

 private:
  std::size_t indexOf(const std::string& name) const {
    for (std::size_t i = 0; i < mSpecs.size(); ++i)
      if (mSpecs[i].name == name) return i;
    std::string names;
    for (const auto& s : mSpecs) names += (names.empty() ? "" : ", ") + s.name;
    throw RequestError("technique '" + mTechnique + "' has no knob '" + name +
                       "'; its knobs are: " + (names.empty() ? "none" : names));
  }

  void validate(const KnobSpec& spec, const std::string& value) const {
    const std::string what = "technique '" + mTechnique + "' knob " + spec.name;
    switch (spec.kind) {
      case KnobKind::Integer:
      case KnobKind::Real: {
        double v = 0;
        if (!detail::parseReal(value, v))
          throw RequestError(what + " must be a finite number, not '" + value + "'");
        const bool below = spec.minExclusive ? !(v > spec.min) : !(v >= spec.min);
        const bool notInteger = spec.kind == KnobKind::Integer && v != std::floor(v);
        if (below || v > spec.max || notInteger)
          throw RequestError(
              what + " must be " + (spec.kind == KnobKind::Integer ? "an integer " : "") +
              (std::isinf(spec.max) ? "" : "in ") + spec.rangeText() + ", not " + value);
        return;
      }
      case KnobKind::Choice:
        for (const auto& c : spec.choices)
          if (c == value) return;
        throw RequestError(what + " must be " + spec.rangeText() + ", not '" + value + "'");
      case KnobKind::OutputFile: {
        const auto& ext = spec.extension;
        if (!value.empty() && (value.size() <= ext.size() ||
                               value.compare(value.size() - ext.size(), ext.size(), ext)))
          throw RequestError(what + "='" + value + "' must name a " + ext + " file");
        return;
      }
      case KnobKind::Text:
        return;
    }
  }

  std::vector<KnobSpec> mSpecs;
  std::vector<std::string> mValues;
  std::string mTechnique;
};

}  // namespace lucent::technique
