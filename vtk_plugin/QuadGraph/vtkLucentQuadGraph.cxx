#include "vtkLucentQuadGraph.h"

#include <vtkObjectFactory.h>

#include <lucent/technique/registry.hpp>

#include "technique/techniques.hpp"
#include "vtkLucentFilter.h"

vtkStandardNewMacro(vtkLucentQuadGraph);

bool vtkLucentQuadGraph::Register() {
  lucent::technique::Registry& registry = vtkLucentFilter::Techniques();
  if (!registry.find("quadgraph")) registry.add(lucent::technique::quadgraphTechnique());
  return registry.find("quadgraph") != nullptr;
}

namespace {
const bool registeredOnLoad = vtkLucentQuadGraph::Register();
}  // namespace
