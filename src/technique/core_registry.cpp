#include "core_registry.hpp"

#include <lucent/technique/core_techniques.hpp>

namespace lucent::technique {

Registry compiledCoreRegistry() { return coreRegistry(); }

}  // namespace lucent::technique
