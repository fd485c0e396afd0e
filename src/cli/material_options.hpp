#pragma once
/// @file material_options.hpp
/// @brief --material / --sigma-a / --sigma-s / --eta, for commands that need a material but no scene.
#include <lucent/optics/materials.hpp>

#include "args.hpp"

namespace lucent::cli {

std::vector<OptionSpec> materialOptionSpecs();
/// Throws InputError with the fix when the material is unknown or invalid.
optics::Material materialFromArgs(const Args& args, const char* fallbackName);

}  // namespace lucent::cli
