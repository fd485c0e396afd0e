/// Writes the ParaView plugin's server-manager XML: the template (LucentPlugin.xml.in) with the
/// filter's technique choice and one property per knob of every technique the filter offers, all
/// derived from the technique descriptions (lucent/technique), so no name, default, range or help
/// is written twice.
///   generate_plugin_xml TEMPLATE OUTPUT
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <lucent/plan/planner.hpp>
#include <lucent/technique/core_techniques.hpp>

#include "vtkLucentFilter.h"

namespace {
namespace lt = lucent::technique;
constexpr const char* kFilterMarker = "<!-- @LUCENT_FILTER_TECHNIQUE_PROPERTIES@ -->";
constexpr const char* kViewMarker = "<!-- @LUCENT_VIEW_TECHNIQUE_PROPERTIES@ -->";
constexpr const char* kSharedBegin = "<!-- @LUCENT_SHARED_FILTER_PROPERTIES_BEGIN@ -->\n";
constexpr const char* kSharedEnd = "<!-- @LUCENT_SHARED_FILTER_PROPERTIES_END@ -->\n";
constexpr const char* kSharedAt = "<!-- @LUCENT_SHARED_FILTER_PROPERTIES@ -->\n";

std::string escape(const std::string& s) {
  std::string out;
  for (const char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string number(double v) {
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

bool fitsInt(double v) {
  return v >= double(std::numeric_limits<int>::min()) &&
         v <= double(std::numeric_limits<int>::max());
}

/// The domain's minimum: a range domain is inclusive, so an exclusive bound (c > 0) becomes the
/// next representable value above it.
double minimum(const lt::KnobSpec& k, bool integer) {
  if (!k.minExclusive) return k.min;
  return integer ? k.min + 1 : std::nextafter(k.min, std::numeric_limits<double>::infinity());
}

/// The element, command and domain of one knob's property. It passes the qualified knob name
/// first (initial_string) and shows only for its technique: the filter's properties are named
/// after the knob ("TsisSamples"), the view's "Lucent" + that ("LucentTsisSamples").
std::string property(const lt::Technique& t, lt::KnobSpec k, bool forFilter) {
  const std::string name = (forFilter ? "" : "Lucent") + lt::propertyName(t, k);
  const bool integer = k.kind == lt::KnobKind::Integer && fitsInt(k.min) && fitsInt(k.max);
  const bool real = k.kind == lt::KnobKind::Real || (k.kind == lt::KnobKind::Integer && !integer);
  const char* element = integer ? "IntVectorProperty"
                        : real  ? "DoubleVectorProperty"
                                : "StringVectorProperty";
  const std::string command = std::string(forFilter ? "" : "SetLucent") +
                              (forFilter ? "SetKnob" : "Knob") +
                              (integer ? "Integer"
                               : real  ? "Real"
                                       : "");
  const std::string technique = forFilter ? "Technique" : "LucentTechnique";
  std::ostringstream o;
  // No label: ParaView's Python names follow the label, and must be the property names front ends
  // use.
  o << "      <" << element << " name=\"" << name << "\" command=\"" << command << "\" ";
  o << "initial_string=\"" << escape(lt::qualifiedName(t, k)) << "\" ";
  o << "number_of_elements=\"1\" default_values=\"" << escape(k.defaultValue) << "\">\n";
  if (integer || real) {
    o << "        <" << (integer ? "IntRangeDomain" : "DoubleRangeDomain")
      << " name=\"range\" min=\"" << number(minimum(k, integer)) << "\"";
    if (!std::isinf(k.max)) o << " max=\"" << number(k.max) << "\"";
    o << " />\n";
  }
  if (k.kind == lt::KnobKind::Choice) {
    o << "        <StringListDomain name=\"list\">\n";
    for (const auto& c : k.choices) o << "          <String value=\"" << escape(c) << "\" />\n";
    o << "        </StringListDomain>\n";
  }
  std::string doc = k.help;
  if (k.kind != lt::KnobKind::Text)
    doc += " (" + k.rangeText() + (k.unit.empty() ? "" : " " + k.unit) + ")";
  o << "        <Documentation>" << escape(doc) << "</Documentation>\n";
  o << "        <Hints>\n          <PropertyWidgetDecorator type=\"GenericDecorator\" "
       "mode=\"visibility\" "
    << "property=\"" << technique << "\" value=\"" << escape(t.name) << "\" />\n        </Hints>\n";
  o << "      </" << element << ">\n";
  return o.str();
}

/// The filter's Technique choice and every offered technique's knob properties.
std::string filterProperties(const lt::Registry& registry) {
  std::ostringstream o;
  o << "      <StringVectorProperty name=\"Technique\" command=\"SetTechnique\" "
       "number_of_elements=\"1\" "
    << "default_values=\"" << escape(registry.defaultReference().name) << "\">\n"
    << "        <StringListDomain name=\"list\">\n";
  for (const lt::Technique* t : lt::vertexTechniques(registry))
    o << "          <String value=\"" << escape(t->name) << "\" />\n";
  o << "          <String value=\"" << lucent::plan::kAutomatic << "\" />\n";
  o << "        </StringListDomain>\n        <Documentation>The technique (lucent techniques lists "
       "them with their papers and capabilities), or "
    << lucent::plan::kAutomatic
    << ": the planner's choice within BudgetMs and MaxError (lucent plan)."
       "</Documentation>\n      </StringVectorProperty>\n";
  for (const auto& [t, k] : lt::knobProperties(registry)) o << property(*t, *k, true);
  return o.str();
}

/// The view's technique choice (the techniques whose GPU twin is the pass) and a property for each
/// knob a twin shares with its technique, with the twin's own bound.
std::string viewProperties(const lt::Registry& registry) {
  std::ostringstream o, knobs;
  std::vector<std::string> twins;
  for (const auto& t : registry.all())
    if (t.capabilities.gpuTwin == "vtkLucentPass") {
      twins.push_back(t.name);
      for (const auto& twin : t.capabilities.gpuTwinKnobs) {
        lt::KnobSpec k = *t.knob(twin.knob);
        k.max = std::min(k.max, twin.max);  // the twin's own bound
        knobs << property(t, k, false);
      }
    }
  o << "      <StringVectorProperty name=\"LucentTechnique\" command=\"SetLucentTechnique\" "
       "number_of_elements=\"1\" default_values=\""
    << escape(twins.empty() ? "" : twins.front())
    << "\">\n        <StringListDomain name=\"list\">\n";
  for (const auto& name : twins) o << "          <String value=\"" << escape(name) << "\" />\n";
  o << "          <String value=\"" << lucent::plan::kAutomatic << "\" />\n";
  o << "        </StringListDomain>\n        <Documentation>The technique whose GPU twin shades "
       "the view (lucent techniques lists them), or "
    << lucent::plan::kAutomatic
    << ": the planner's choice per frame, within LucentMaxError.</Documentation>\n"
       "      </StringVectorProperty>\n";
  return o.str() + knobs.str();
}

bool replaceMarker(std::string& xml, const std::string& marker, const std::string& with) {
  const auto at = xml.find(marker);
  if (at == std::string::npos) return false;
  xml.replace(at, marker.size(), with);
  return true;
}

/// Copies the filter's properties between the BEGIN and END markers (scene and technique) to the
/// volume filter's marker: one definition for both proxies (ParaView's proxy inheritance crashes
/// ParaView 5.11 on a SourceProxy that redefines Input).
bool copySharedProperties(std::string& xml) {
  const auto begin = xml.find(kSharedBegin), end = xml.find(kSharedEnd);
  if (begin == std::string::npos || end == std::string::npos || end < begin) return false;
  const std::string shared =
      xml.substr(begin + std::strlen(kSharedBegin), end - begin - std::strlen(kSharedBegin));
  xml.erase(end, std::strlen(kSharedEnd));
  xml.erase(begin, std::strlen(kSharedBegin));
  return replaceMarker(xml, kSharedAt, shared);
}
}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: generate_plugin_xml TEMPLATE OUTPUT\n";
    return 2;
  }
  std::ifstream in(argv[1]);
  std::stringstream text;
  text << in.rdbuf();
  std::string xml = text.str();
  const lt::Registry& registry = vtkLucentFilter::Techniques();
  if (!in || !replaceMarker(xml, kFilterMarker, filterProperties(registry)) ||
      !replaceMarker(xml, kViewMarker, viewProperties(registry)) || !copySharedProperties(xml)) {
    std::cerr << "generate_plugin_xml: " << argv[1] << " lacks " << kFilterMarker << ", "
              << kViewMarker << " or the shared-properties markers\n";
    return 2;
  }
  std::ofstream out(argv[2]);
  out << xml;
  return out ? 0 : 1;
}
