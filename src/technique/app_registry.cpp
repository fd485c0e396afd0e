#include "core_registry.hpp"
#include "techniques.hpp"

namespace lucent::technique {

Registry& appRegistry() {
  static Registry registry = [] {
    Registry r = compiledCoreRegistry();
    r.add(prtTechnique());
#ifdef LUCENT_HAVE_TETGEN
    r.add(quadgraphTechnique());
#endif
    return r;
  }();
  return registry;
}

}  // namespace lucent::technique
