#pragma once
/// @file knobs.hpp
/// @brief The CLI spelling of knob settings: "name=value[,name=value...]". The knobs themselves
/// (types, defaults, ranges) are declared by each technique (lucent/technique/knob.hpp).
#include <map>
#include <string>

namespace lucent::render {

/// "spacing=0.1,fraction=0.5" -> map; throws InputError on a malformed pair.
std::map<std::string, std::string> parseKnobList(const std::string& text);

}  // namespace lucent::render
