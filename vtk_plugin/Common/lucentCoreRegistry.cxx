// The registries of lucentFilterTechniques.h, compiled once per module. The core registry is
// lucent_core_registry's (LUCENT_COMPILED_CORE_REGISTRY), which lucent's build and the ParaView tree
// compile once for every module; an embedder's build without it instantiates it here from the headers.
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
