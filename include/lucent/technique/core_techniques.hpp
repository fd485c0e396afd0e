#pragma once
/// @file core_techniques.hpp
/// @brief The header-only techniques (STL + GLM, services through SceneDescription). Adding one is
/// one file and one line here; techniques that need a heavy library register from their adapter in
/// src/.
#include "diffuse_brdf.hpp"
#include "dipole_sum.hpp"
#include "optical_thickness.hpp"
#include "path_tracing.hpp"
#include "random_walk.hpp"
#include "registry.hpp"
#include "texture_space.hpp"
#include "voxel_single.hpp"

namespace lucent::technique {

inline void addCoreTechniques(Registry& registry) {
  registry.add(referenceTechnique());
  registry.add(jensenBuhlerTechnique());
  registry.add(tsisTechnique());
  registry.add(hybridTechnique());
  registry.add(tsmTechnique());
  registry.add(diffuseBrdfTechnique());
  registry.add(taulutTechnique());
  registry.add(voxelSingleTechnique());
  registry.add(pathtraceTechnique());
  registry.add(randomwalkTechnique());
}

/// A registry holding the core techniques: what the VTK filter and the ParaView XML generator
/// offer.
inline Registry coreRegistry() {
  Registry r;
  addCoreTechniques(r);
  return r;
}

}  // namespace lucent::technique
