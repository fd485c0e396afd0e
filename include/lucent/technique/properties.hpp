#pragma once
/// @file properties.hpp
/// @brief How object-property front ends (the VTK filter, the generated ParaView XML) spell
/// techniques and knobs, and which they offer: derived here, once, from the registry's
/// descriptions.
#include <string>

#include "technique.hpp"

namespace lucent::technique {

/// "tsis.samples": a knob named across techniques.
inline std::string qualifiedName(const Technique& t, const KnobSpec& k) {
  return t.name + "." + k.name;
}
/// "TsisSamples": the CamelCase of the qualified name, a VTK / ParaView property name.
inline std::string propertyName(const Technique& t, const KnobSpec& k) {
  return camelCase(qualifiedName(t, k));
}
/// Whether a front end that shades a mesh's vertices without a camera can offer the technique.
inline bool shadesVertices(const Technique& t) {
  return t.capabilities.perVertex && !t.capabilities.needsCamera;
}
/// Whether the knob is an object property: output files are written by the CLI, not by a filter.
inline bool isProperty(const KnobSpec& k) { return k.kind != KnobKind::OutputFile; }

}  // namespace lucent::technique
