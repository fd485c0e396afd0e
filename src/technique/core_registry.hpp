#pragma once
/// @file core_registry.hpp
/// @brief The core techniques' registry compiled once (core_registry.cpp), for lucent's own CLI,
/// tests and benchmarks. A translation unit that builds it from core_techniques.hpp instantiates
/// every technique, about 30 s of compiling at -O3; a dozen such units made CI slow. Embedders
/// include core_techniques.hpp and call coreRegistry() as before.
#include <lucent/technique/registry.hpp>

namespace lucent::technique {

/// A fresh registry holding the core techniques (the same as coreRegistry()).
Registry compiledCoreRegistry();

}  // namespace lucent::technique
