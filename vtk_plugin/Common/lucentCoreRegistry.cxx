// The registries of lucentFilterTechniques.h, compiled once per module. In lucent's own build the
// core registry is the one lucent_core_registry compiled for the CLI
// (LUCENT_COMPILED_CORE_REGISTRY); against ParaView's VTK it is instantiated here from the headers.
#include "lucentFilterTechniques.h"

#ifdef LUCENT_COMPILED_CORE_REGISTRY
#include "technique/core_registry.hpp"
#else
#include <lucent/technique/core_techniques.hpp>
#endif
#include "technique/techniques.hpp"

namespace lucent::vtkadapter {

technique::Registry coreTechniques() {
#ifdef LUCENT_COMPILED_CORE_REGISTRY
  return technique::compiledCoreRegistry();
#else
  return technique::coreRegistry();
#endif
}

#ifdef LUCENT_FILTER_TECHNIQUES  // the Filters module, which compiles prt's adapter in
technique::Registry filterTechniques() {
  technique::Registry r = coreTechniques();
  r.add(technique::prtTechnique());
  return r;
}
#endif

}  // namespace lucent::vtkadapter
