/// Writes the ParaView plugin's server-manager XML: the template (LucentPlugin.xml.in) with the
/// filter's technique choice and one property per knob of every technique the filter offers, all
/// derived from the technique descriptions (lucent/technique), so no name, default, range or help
/// is written twice.
///   generate_plugin_xml TEMPLATE OUTPUT
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>

#include <lucent/technique/core_techniques.hpp>

namespace {
namespace lt = lucent::technique;
constexpr const char* kMarker = "<!-- @LUCENT_FILTER_TECHNIQUE_PROPERTIES@ -->";

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

/// The element, command and domain of one knob's property.
std::string property(const lt::Technique& t, const lt::KnobSpec& k) {
  const std::string name = lt::propertyName(t, k), qualified = lt::qualifiedName(t, k);
  const bool integer = k.kind == lt::KnobKind::Integer && fitsInt(k.min) && fitsInt(k.max);
  const bool real = k.kind == lt::KnobKind::Real || (k.kind == lt::KnobKind::Integer && !integer);
  const char* element = integer ? "IntVectorProperty"
                        : real  ? "DoubleVectorProperty"
                                : "StringVectorProperty";
  const char* command = integer ? "SetKnobInteger" : real ? "SetKnobReal" : "SetKnob";
  std::ostringstream o;
  // No label: ParaView's Python names follow the label, and must be the property names front ends
  // use.
  o << "      <" << element << " name=\"" << name << "\" command=\"" << command
    << "\" initial_string=\"" << escape(qualified)
    << "\" number_of_elements=\"1\" default_values=\"" << escape(k.defaultValue) << "\">\n";
  if (integer || real) {
    o << "        <" << (integer ? "IntRangeDomain" : "DoubleRangeDomain")
      << " name=\"range\" min=\"" << number(k.min) << "\"";
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
  o << "        <Documentation>" << escape(doc) << "</Documentation>\n"
    << "        <Hints>\n          <PropertyWidgetDecorator type=\"GenericDecorator\" "
       "mode=\"visibility\" "
       "property=\"Technique\" value=\""
    << escape(t.name) << "\" />\n        </Hints>\n      </" << element << ">\n";
  return o.str();
}

std::string techniqueProperties(const lt::Registry& registry) {
  std::ostringstream o;
  o << "      <StringVectorProperty name=\"Technique\" command=\"SetTechnique\" "
       "number_of_elements=\"1\" "
       "default_values=\"reference\">\n        <StringListDomain name=\"list\">\n";
  for (const auto& t : registry.all())
    if (lt::shadesVertices(t)) o << "          <String value=\"" << escape(t.name) << "\" />\n";
  o << "        </StringListDomain>\n        <Documentation>The technique (lucent techniques lists "
       "them with their "
       "papers and capabilities).</Documentation>\n      </StringVectorProperty>\n";
  for (const auto& t : registry.all())
    if (lt::shadesVertices(t))
      for (const auto& k : t.knobs)
        if (lt::isProperty(k)) o << property(t, k);
  return o.str();
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
  const auto at = xml.find(kMarker);
  if (!in || at == std::string::npos) {
    std::cerr << "generate_plugin_xml: " << argv[1] << " has no " << kMarker << "\n";
    return 2;
  }
  lt::Registry registry;
  lt::addCoreTechniques(registry);  // the registry vtkLucentFilter::Techniques() holds
  xml.replace(at, std::string(kMarker).size(), techniqueProperties(registry));
  std::ofstream out(argv[2]);
  out << xml;
  return out ? 0 : 1;
}
