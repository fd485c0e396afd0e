#pragma once
/// @file transfer_function.hpp
/// @brief `--transfer SPEC`: a scan's values turned into coefficients per channel, the medium of a
/// `--volume` object.
///  - "labels:V=MATERIAL,V=MATERIAL,...": a label map; each label (the value rounded) is a measured
///    material or "none" (no medium: outside, or a cavity). The object's surface is then where the
///    labels with a material meet the others, so --iso is not needed; a label in the scan with no
///    entry is an error naming it.
///  - "points:V/SA/SS;V/SA/SS;...": piecewise linear in the value between control points (sorted by
///    V, held beyond the ends), SA = sigma_a and SS = sigma_s' as R,G,B in mm^-1, e.g.
///    points:100/0.01,0.02,0.05/0.5,0.6,0.7;400/0.1,0.2,0.3/2,2,2.
#include <memory>
#include <string>

#include <lucent/scene/voxel_grid.hpp>
#include <lucent/technique/scene.hpp>

namespace lucent::cli {

struct ScanMedium {
  technique::CoefficientField field;  ///< in the scan's millimetres
  glm::dvec3 maxSigmaT{0};            ///< sigma_a + sigma_s' never above, per channel
  std::string description;
  /// Labels: 1 where the label has a material, 0 elsewhere (contoured at 1/2 for the surface).
  std::shared_ptr<const scene::VoxelGrid> mask;
};

/// Throws InputError naming `what`, the problem and the fix.
ScanMedium parseTransfer(const std::string& what, const std::string& spec,
                         std::shared_ptr<const scene::VoxelGrid> scan);

}  // namespace lucent::cli
