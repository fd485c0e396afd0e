#include "vtkLucentQuadGraph.h"

#include <string>
#include <utility>

#include <vtkObjectFactory.h>

#include <lucent/technique/registry.hpp>

#include "technique/techniques.hpp"
#include "vtkLucentFilter.h"

vtkStandardNewMacro(vtkLucentQuadGraph);

bool vtkLucentQuadGraph::Register() {
  lucent::technique::Registry& registry = vtkLucentFilter::Techniques();
  lucent::technique::Technique quadgraph = lucent::technique::quadgraphTechnique();
  const std::string name = quadgraph.name;
  if (!registry.find(name)) registry.add(std::move(quadgraph));
  return registry.find(name) != nullptr;
}

namespace {
const bool registeredOnLoad = vtkLucentQuadGraph::Register();
}  // namespace
