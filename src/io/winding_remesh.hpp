#pragma once
/// @file winding_remesh.hpp
/// @brief The repair that always succeeds for a soup that encloses something: its generalized
/// winding number (scene/winding_number.hpp) sampled on a grid, inside where it exceeds 1/2, signed
/// by that and sized by the distance to the soup near the surface, and re-extracted as the closed
/// isosurface of a scan is (vtkadapter::closedIsosurface: a 2-manifold at any threshold). Holes of
/// any size close where the field crosses 1/2; flips, overlaps and non-manifold edges vanish.
/// Features thinner than a voxel may vanish too: the report measures how far the result lies from
/// the input.
#include <string>

#include <lucent/scene/mesh.hpp>

namespace lucent::io {

/// Voxels along the longest side of the mesh's bounding box, by default and at most.
inline constexpr int kDefaultRemeshResolution = 128;
/// 512 keeps the grid and its copies under about 2 GB (134 M nodes).
inline constexpr int kMinRemeshResolution = 16, kMaxRemeshResolution = 512;

struct RemeshResult {
  scene::TriangleMesh mesh;  ///< closed, manifold, outward; the input's units
  double voxel = 0;          ///< the grid's spacing, the input's units
  /// Distances over the vertices: of the result to the input soup, and of the input to the result.
  double resultToInputMax = 0, resultToInputMean = 0;
  double inputToResultMax = 0, inputToResultMean = 0;
};

/// Remeshes `soup` at `resolution` voxels along its longest side; the distances are measured
/// against `input` (the mesh as the user gave it; may be `soup`). Throws InputError naming `what`
/// when the soup encloses nothing (its winding number nowhere exceeds 1/2: an open sheet, lines).
RemeshResult remeshByWindingNumber(const scene::TriangleMesh& soup,
                                   const scene::TriangleMesh& input, int resolution,
                                   const std::string& what);

}  // namespace lucent::io
