#include "methods.hpp"

#include "../util/error.hpp"

namespace lucent::render {

Method referenceMethod();
Method jensenBuhlerMethod();
Method tsisMethod();
Method hybridMethod();
Method tsmMethod();
Method pathtraceMethod();
#ifdef LUCENT_HAVE_TETGEN
Method quadgraphMethod();
#endif

const std::vector<Method>& methods() {
  static const std::vector<Method> all{referenceMethod(), jensenBuhlerMethod(), tsisMethod(), hybridMethod(),
                                         tsmMethod(), pathtraceMethod()
#ifdef LUCENT_HAVE_TETGEN
                                             ,
                                         quadgraphMethod()
#endif
  };
  return all;
}

const Method& findMethod(const std::string& name) {
  for (const auto& m : methods())
    if (m.name == name) return m;
  std::string names;
  for (const auto& m : methods()) names += (names.empty() ? "" : ", ") + m.name;
  throw InputError("unknown method '" + name + "'; available: " + names);
}

}  // namespace lucent::render
