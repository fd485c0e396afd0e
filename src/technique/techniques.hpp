#pragma once
/// @file techniques.hpp
/// @brief The registry the lucent application (CLI, bench, examples) reads: the core techniques
/// plus those whose adapters need a heavy library.
#include <lucent/technique/registry.hpp>

namespace lucent::technique {

#ifdef LUCENT_HAVE_TETGEN
Technique quadgraphTechnique();  ///< quadgraph_technique.cpp (links TetGen, AGPL)
#endif

Technique prtTechnique();  ///< prt_technique.cpp (the phase function's SVD links Eigen)

/// Built on first use; tests may add techniques of their own before running a front end.
Registry& appRegistry();

}  // namespace lucent::technique
