/// @file lucentFilterTechniques.h
/// @brief The techniques the VTK filter (and so ParaView's Lucent Translucent) offers: the core's
/// header-only techniques and prt, whose adapter (src/technique/prt_technique.cpp, Eigen for the
/// phase function's SVD) the Lucent::Filters module compiles in. quadgraph's adapter links TetGen
/// (AGPL) and stays out. The ParaView XML generator reads the same list.
#ifndef lucentFilterTechniques_h
#define lucentFilterTechniques_h

#include <lucent/technique/core_techniques.hpp>

#include "technique/techniques.hpp"

namespace lucent::vtkadapter {

inline technique::Registry filterTechniques() {
  technique::Registry r = technique::coreRegistry();
  r.add(technique::prtTechnique());
  return r;
}

}  // namespace lucent::vtkadapter

#endif
