/// Writes the ParaView plugin's server-manager XML: the template (LucentPlugin.xml.in) with the
/// filter's technique choice and one property per knob of every technique the filter offers, all
/// derived from the technique descriptions (lucent/technique), so no name, default, range or help
/// is written twice.
///   generate_plugin_xml TEMPLATE OUTPUT
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <lucent/technique/core_techniques.hpp>

namespace {
namespace lt = lucent::technique;
constexpr const char* kFilterMarker = "<!-- @LUCENT_FILTER_TECHNIQUE_PROPERTIES@ -->";
constexpr const char* kViewMarker = "<!-- @LUCENT_VIEW_TECHNIQUE_PROPERTIES@ -->";

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

/// The element, command and domain of one knob's property. A filter property passes the qualified
/// knob name first (initial_string) and shows only for its technique; a view property has a setter
/// of its own.
std::string property(const lt::Technique& t, lt::KnobSpec k, bool forFilter) {
  const std::string name = forFilter ? lt::propertyName(t, k) : "Lucent" + lt::camelCase(k.name);
  const bool integer = k.kind == lt::KnobKind::Integer && fitsInt(k.min) && fitsInt(k.max);
  const bool real = k.kind == lt::KnobKind::Real || (k.kind == lt::KnobKind::Integer && !integer);
  const char* element = integer ? "IntVectorProperty"
                        : real  ? "DoubleVectorProperty"
                                : "StringVectorProperty";
  const std::string command = forFilter ? (integer ? "SetKnobInteger"
                                           : real  ? "SetKnobReal"
                                                   : "SetKnob")
                                        : "Set" + name;
  std::ostringstream o;
  // No label: ParaView's Python names follow the label, and must be the property names front ends
  // use.
  o << "      <" << element << " name=\"" << name << "\" command=\"" << command << "\" ";
  if (forFilter) o << "initial_string=\"" << escape(lt::qualifiedName(t, k)) << "\" ";
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
  if (forFilter)
    o << "        <Hints>\n          <PropertyWidgetDecorator type=\"GenericDecorator\" "
         "mode=\"visibility\" "
      << "property=\"Technique\" value=\"" << escape(t.name) << "\" />\n        </Hints>\n";
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
  o << "        </StringListDomain>\n        <Documentation>The technique (lucent techniques lists "
       "them with "
    << "their papers and capabilities).</Documentation>\n      </StringVectorProperty>\n";
  for (const auto& [t, k] : lt::knobProperties(registry)) o << property(*t, *k, true);
  return o.str();
}

/// The view's properties for the knobs its GPU pass shares with the technique it is the twin of.
std::string viewProperties(const lt::Registry& registry) {
  std::ostringstream o;
  for (const auto& t : registry.all())
    if (t.capabilities.gpuTwin == "vtkLucentPass")
      for (const auto& twin : t.capabilities.gpuTwinKnobs) {
        lt::KnobSpec k = *t.knob(twin.knob);
        k.max = std::min(k.max, twin.max);  // the twin's own bound
        o << property(t, k, false);
      }
  return o.str();
}

bool replaceMarker(std::string& xml, const std::string& marker, const std::string& with) {
  const auto at = xml.find(marker);
  if (at == std::string::npos) return false;
  xml.replace(at, marker.size(), with);
  return true;
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
  const lt::Registry registry = lt::coreRegistry();  // what vtkLucentFilter::Techniques() holds
  if (!in || !replaceMarker(xml, kFilterMarker, filterProperties(registry)) ||
      !replaceMarker(xml, kViewMarker, viewProperties(registry))) {
    std::cerr << "generate_plugin_xml: " << argv[1] << " lacks " << kFilterMarker << " or "
              << kViewMarker << "\n";
    return 2;
  }
  std::ofstream out(argv[2]);
  out << xml;
  return out ? 0 : 1;
}
