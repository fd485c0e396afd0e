/// @file lucentFilterTechniques.h
/// @brief The techniques the VTK filter (and so ParaView's Lucent Translucent) offers: the core's
/// header-only techniques and prt, whose adapter (src/technique/prt_technique.cpp, Eigen for the
/// phase function's SVD) the Lucent::Filters module compiles in. quadgraph's adapter links TetGen
/// (AGPL) and stays out. The ParaView XML generator reads the same list.
#ifndef lucentFilterTechniques_h
#define lucentFilterTechniques_h

#include <lucent/technique/registry.hpp>

namespace lucent::vtkadapter {

/// The core registry and prt. Compiled in one unit (lucentCoreRegistry.cxx): building the core
/// registry instantiates every technique, about a minute of compiling.
technique::Registry filterTechniques();

/// The core registry alone (the GPU pass's twins).
technique::Registry coreTechniques();

}  // namespace lucent::vtkadapter

#endif
